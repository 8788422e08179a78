#include "common/json_parse.h"

#include <fmt/format.h>

#include "common/error.h"

namespace echoplan {

nlohmann::json parse_json(const std::string& text, const std::string& source) {
  // The callback sees each value's depth as the parser reaches it (an object's keys one level
  // below the object): throwing there stops the parse before the deep part is built.
  return nlohmann::json::parse(
      text, [&source](int depth, nlohmann::json::parse_event_t, const nlohmann::json&) {
        if (depth > kMaxJsonDepth)
          throw InputError(source, 0,
                           fmt::format("JSON nested deeper than {} arrays and objects: not a file "
                                       "echoplan writes (corrupt or hostile?)",
                                       kMaxJsonDepth));
        return true;
      });
}

}  // namespace echoplan
