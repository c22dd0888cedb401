// "Did you mean": edit distances and the suggestions a misspelt scene gets.
#include "membra/core/did_you_mean.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "membra/core/input_error.hpp"
#include "membra/io/scene.hpp"

namespace membra {
namespace {

TEST(DidYouMean, EditDistanceCountsSingleCharacterEdits) {
  EXPECT_EQ(edit_distance("", ""), 0u);
  EXPECT_EQ(edit_distance("resolution", "resolution"), 0u);
  EXPECT_EQ(edit_distance("resolutoin", "resolution"), 2u);  // a swap is two edits
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("epoxy", ""), 5u);
}

TEST(DidYouMean, SuggestsOnlyWhatIsCloseEnoughToBeATypo) {
  const std::vector<std::string_view> known = {"size", "resolution", "material", "bending"};
  EXPECT_EQ(did_you_mean("resolutoin", known), " (did you mean 'resolution'?)");
  EXPECT_EQ(did_you_mean("materail", known), " (did you mean 'material'?)");
  EXPECT_EQ(did_you_mean("colour", known), "");
}

// The scene's own messages: an unknown key, value and material each name the nearest known word
// and list the known ones.
TEST(DidYouMean, AMisspeltSceneIsToldWhatItMeant) {
  const auto message = [](const nlohmann::json& j) {
    try {
      parse_scene(j);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  nlohmann::json j = nlohmann::json::parse(R"({"sheet": {"size": [100, 100],
    "resolution": [11, 11], "materail": "latex"}})");
  std::string m = message(j);
  EXPECT_NE(m.find("did you mean 'material'?"), std::string::npos) << m;
  EXPECT_NE(m.find("known here: "), std::string::npos) << m;
  j["sheet"].erase("materail");
  j["sheet"]["material"] = "latx";
  m = message(j);
  EXPECT_NE(m.find("did you mean 'latex'?"), std::string::npos) << m;
  EXPECT_NE(m.find("known: epoxy, latex"), std::string::npos) << m;
  j["sheet"]["material"] = "latex";
  j["model"] = "continum";
  m = message(j);
  EXPECT_NE(m.find("did you mean 'continuum'?"), std::string::npos) << m;
}

}  // namespace
}  // namespace membra
