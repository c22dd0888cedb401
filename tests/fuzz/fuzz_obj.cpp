// libFuzzer target: any bytes as an OBJ target mesh. Every triangle read must index a vertex.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "membra/core/input_error.hpp"
#include "membra/io/obj.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const membra::ObjMesh m = membra::read_obj(in, "fuzz.obj");
    for (const auto& t : m.triangles)
      for (int k = 0; k < 3; ++k)
        if (t[k] < 0 || t[k] >= m.x.cols()) __builtin_trap();
    if (!m.x.allFinite()) __builtin_trap();
  } catch (const membra::InputError&) {
  }
  return 0;
}
