#pragma once
// A grey raster, values 0 (black) .. 1 (white), row 0 at the top: PNG masks and fields as the
// model uses them (io/image.hpp reads them).
#include <vector>

namespace membra {

struct GreyImage {
  int width = 0, height = 0;
  std::vector<float> value;
};

}  // namespace membra
