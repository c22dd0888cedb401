#pragma once
// The error every input check throws: it names where the bad value is (a file and/or a JSON
// pointer such as /simulation/T) so a user can find it.
#include <stdexcept>
#include <string>

namespace membra {

class InputError : public std::runtime_error {
 public:
  // `where` is a JSON pointer ("/sheet/size/0"), a file, or both; `detail` says what is wrong.
  InputError(std::string where, std::string detail)
      : std::runtime_error(where.empty() ? detail : where + ": " + detail),
        where_(std::move(where)),
        detail_(std::move(detail)) {}
  const std::string& where() const { return where_; }
  const std::string& detail() const { return detail_; }

 private:
  std::string where_;
  std::string detail_;
};

}  // namespace membra
