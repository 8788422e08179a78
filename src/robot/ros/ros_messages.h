// The echoplan_ros messages and services, and audio_common_msgs' AudioData and AudioInfo, usable
// from C++20.
//
// Debian's roscpp_serialization (1.15) serializes std::vector fields through
// `ContainerAllocator::rebind<T>::other`, which C++20 removed from std::allocator, so any message
// with an array field fails to compile in a C++20 translation unit. The full specializations below,
// for the element types echoplan's messages use, take precedence over roscpp's partial ones and
// write the same bytes (a uint32 length, then the elements: raw memory for numbers, length-prefixed
// for strings). Include this header, never the generated ones directly.
#pragma once

#include <ros/serialization.h>

#include <cstring>
#include <string>
#include <vector>

namespace ros::serialization {

// uint8[], float32[] and float64[]: fixed-size simple elements, copied as raw memory.
template <typename T>
struct SimpleVectorSerializer {
  using VecType = std::vector<T>;
  template <typename Stream>
  static void write(Stream& stream, const VecType& v) {
    const auto len = static_cast<uint32_t>(v.size());
    stream.next(len);
    if (len > 0)
      std::memcpy(stream.advance(len * static_cast<uint32_t>(sizeof(T))), v.data(),
                  len * sizeof(T));
  }
  template <typename Stream>
  static void read(Stream& stream, VecType& v) {
    uint32_t len = 0;
    stream.next(len);
    // The length is the sender's word: checked against the bytes left before anything is
    // allocated, so that a bad one can neither ask for gigabytes nor wrap len * sizeof(T) around
    // 32 bits (which made advance() accept a short buffer that memcpy then overran).
    if (len > stream.getLength() / sizeof(T)) throwStreamOverrun();
    v.resize(len);
    if (len > 0)
      std::memcpy(v.data(), stream.advance(len * static_cast<uint32_t>(sizeof(T))),
                  len * sizeof(T));
  }
  static uint32_t serializedLength(const VecType& v) {
    return 4 + static_cast<uint32_t>(v.size() * sizeof(T));
  }
};

template <>
struct VectorSerializer<float, std::allocator<float>, void> : SimpleVectorSerializer<float> {};
template <>
struct VectorSerializer<unsigned char, std::allocator<unsigned char>, void>
    : SimpleVectorSerializer<unsigned char> {};
template <>
struct VectorSerializer<double, std::allocator<double>, void> : SimpleVectorSerializer<double> {};

// string[]: each element length-prefixed.
template <>
struct VectorSerializer<std::string, std::allocator<std::string>, void> {
  using VecType = std::vector<std::string>;
  template <typename Stream>
  static void write(Stream& stream, const VecType& v) {
    stream.next(static_cast<uint32_t>(v.size()));
    for (const auto& s : v) stream.next(s);
  }
  template <typename Stream>
  static void read(Stream& stream, VecType& v) {
    uint32_t len = 0;
    stream.next(len);
    // Each string takes at least its 4-byte length: a count the bytes left cannot hold is refused
    // before it is allocated.
    if (len > stream.getLength() / 4) throwStreamOverrun();
    v.resize(len);
    for (auto& s : v) stream.next(s);
  }
  static uint32_t serializedLength(const VecType& v) {
    uint32_t size = 4;
    for (const auto& s : v) size += serializationLength(s);
    return size;
  }
};

}  // namespace ros::serialization

#include <audio_common_msgs/AudioData.h>
#include <audio_common_msgs/AudioInfo.h>
#include <echoplan_ros/BeginTrial.h>
#include <echoplan_ros/Clip.h>
#include <echoplan_ros/ExecuteAction.h>
#include <echoplan_ros/FeatureRow.h>
#include <echoplan_ros/Observe.h>
#include <echoplan_ros/RecordingState.h>
