#include "membra/process/protocol.hpp"

namespace membra {

const char* step_name(ProtocolStep::Kind kind) {
  switch (kind) {
    case ProtocolStep::Kind::stretch:
      return "stretch";
    case ProtocolStep::Kind::impregnate:
      return "impregnate";
    case ProtocolStep::Kind::release:
      return "release";
    case ProtocolStep::Kind::load:
      return "load";
    case ProtocolStep::Kind::grow:
      return "grow";
    case ProtocolStep::Kind::add_springs:
      return "add_springs";
    case ProtocolStep::Kind::cut:
      return "cut";
    case ProtocolStep::Kind::curvature_map:
      return "curvature_map";
  }
  return "?";
}

}  // namespace membra
