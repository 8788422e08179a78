#include "robot/ros/series_topic.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <sstream>

#include "common/error.h"
#include "robot/ros/bag_messages.h"

namespace echoplan::robot {

namespace {

// A name that can be a folder of a recordings tree and one word of a marker.
bool plain_name(const std::string& name) {
  return !name.empty() && name[0] != '.' && name.find_first_of("/\\,\" \t\n") == std::string::npos;
}

std::vector<std::string> wrench_channels(const std::string& field) {
  std::vector<std::string> force{"force_x", "force_y", "force_z"};
  const std::vector<std::string> torque{"torque_x", "torque_y", "torque_z"};
  if (field == "force") return force;
  if (field == "torque") return torque;
  force.insert(force.end(), torque.begin(), torque.end());
  return force;
}

std::vector<double> wrench_values(const WrenchMessage& w, const std::string& field) {
  const double* f = w.force;
  const double* t = w.torque;
  if (field == "force") return {f[0], f[1], f[2]};
  if (field == "torque") return {t[0], t[1], t[2]};
  return {f[0], f[1], f[2], t[0], t[1], t[2]};
}

// The message decoded as `type`, after checking that its MD5 sum names the layout read here.
template <typename Decode>
auto decoded(const std::string& md5, const char* type, const char* expected_md5, Decode decode,
             std::span<const std::uint8_t> bytes) {
  if (md5 != expected_md5)
    throw InputError("", 0,
                     fmt::format("a {} (MD5 {}), not the {} this reads (MD5 {})", type, md5, type,
                                 expected_md5));
  return decode(bytes);
}

}  // namespace

SeriesTopic parse_series_topic(const std::string& text) {
  const auto eq = text.find('=');
  auto bad = [&](const std::string& problem) {
    throw InputError("", 0,
                     fmt::format("'{}': {} (expected MODALITY=TOPIC[:FIELD], e.g. "
                                 "effort=/joint_states:effort)",
                                 text, problem));
  };
  if (eq == std::string::npos) bad("no '='");
  SeriesTopic s;
  s.modality = text.substr(0, eq);
  std::string rest = text.substr(eq + 1);
  if (const auto colon = rest.rfind(':'); colon != std::string::npos) {
    s.field = rest.substr(colon + 1);
    rest = rest.substr(0, colon);
  }
  s.topic = rest;
  if (!plain_name(s.modality) || s.modality.find('.') != std::string::npos)
    bad("the modality must be a plain name");
  if (s.modality == "audio") bad("audio is not read as a series");
  if (s.topic.empty()) bad("no topic");
  return s;
}

std::optional<PerformanceMarker> parse_performance_marker(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  if (words.size() == 1 && words[0] == "end") return PerformanceMarker{};
  if (words.size() == 4 && words[0] == "start" && plain_name(words[1]) && plain_name(words[2]) &&
      plain_name(words[3]))
    return PerformanceMarker{true, words[1], words[2], words[3]};
  return std::nullopt;
}

std::string start_marker_text(const std::string& object, const std::string& action,
                              const std::string& session) {
  for (const std::string* name : {&object, &action, &session})
    if (!plain_name(*name))
      throw InputError("", 0,
                       fmt::format("'{}' cannot be a word of a performance marker (a plain name "
                                   "has no spaces, '/', ',' or '\"' and does not start with '.')",
                                   *name));
  return fmt::format("start {} {} {}", object, action, session);
}

SeriesTopicReader::SeriesTopicReader(SeriesTopic spec) : spec_(std::move(spec)) {}

void SeriesTopicReader::first_message(const std::string& type, const std::string& md5,
                                      std::span<const std::uint8_t> bytes) {
  std::string& field = spec_.field;
  if (type == kJointStateType) {
    if (field.empty()) field = "effort";
    if (field != "effort" && field != "position" && field != "velocity")
      throw InputError(
          "", 0,
          fmt::format("a {}: its field is effort, position or velocity, not '{}'", type, field));
    std::vector<std::string> joints =
        decoded(md5, kJointStateType, kJointStateMd5, decode_joint_state, bytes).name;
    if (joints.empty()) throw InputError("", 0, "a joint state naming no joint");
    channels_ = std::move(joints);
  } else if (type == kWrenchStampedType) {
    if (field.empty()) field = "force";
    if (field != "force" && field != "torque" && field != "wrench")
      throw InputError(
          "", 0, fmt::format("a {}: its field is force, torque or wrench, not '{}'", type, field));
    channels_ = wrench_channels(field);
  } else {
    throw InputError(
        "", 0, fmt::format("a {}, not a {} or {}", type, kJointStateType, kWrenchStampedType));
  }
  type_ = type;
}

std::vector<double> SeriesTopicReader::read(const std::string& type, const std::string& md5,
                                            std::span<const std::uint8_t> bytes) {
  ++messages_;
  if (type_.empty()) first_message(type, md5, bytes);
  if (type != type_) throw InputError("", 0, fmt::format("a {} on a topic of {}", type, type_));
  if (type_ == kWrenchStampedType)
    return wrench_values(
        decoded(md5, kWrenchStampedType, kWrenchStampedMd5, decode_wrench_stamped, bytes),
        spec_.field);
  const JointStateMessage js =
      decoded(md5, kJointStateType, kJointStateMd5, decode_joint_state, bytes);
  const std::vector<double>& field = spec_.field == "position"   ? js.position
                                     : spec_.field == "velocity" ? js.velocity
                                                                 : js.effort;
  if (field.size() < js.name.size())
    throw InputError(
        "", 0,
        fmt::format("{} {} values for {} joints", field.size(), spec_.field, js.name.size()));
  std::vector<double> values;
  values.reserve(channels_.size());
  for (const std::string& joint : channels_) {
    const auto at = std::find(js.name.begin(), js.name.end(), joint);
    if (at == js.name.end())
      throw InputError("", 0,
                       fmt::format("no joint '{}' (the topic's first message had {})", joint,
                                   fmt::join(channels_, ", ")));
    values.push_back(field[static_cast<std::size_t>(at - js.name.begin())]);
  }
  return values;
}

}  // namespace echoplan::robot
