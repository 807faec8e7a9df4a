// SPDX-License-Identifier: MIT
#pragma once

// Cyclone DDS's side of a type-agnostic subscription; included by ros2engine.cpp only, so that
// Cyclone stays out of every header other layers see.

#include <atomic>
#include <cstddef>
#include <dds/dds.h>
#include <functional>
#include <QtGlobal>
#include <string>

/// A sample as its CDR bytes, encapsulation header included (a view: valid during the callback).
struct Ros2RawSample
{
    const unsigned char* data = nullptr;
    std::size_t size = 0;
};

/// A type that takes any sample as bytes, whatever its name says (roscpp's ShapeShifter for DDS):
/// a Cyclone sertype whose serdata is the serialized sample as it came, as rmw_cyclonedds_cpp's
/// and tests/ros2peer/peer_sertype.c's are.
namespace Ros2RawType {
/// Samples larger than this are dropped as they arrive (Cyclone counts them as not deserialized).
constexpr std::size_t kMaxSampleBytes = 64 * 1024 * 1024;

/// Topic `name` of DDS type `type` in `participant`, any sample taken as bytes; a negative
/// Cyclone return code when it cannot be made.
dds_entity_t createTopic(dds_entity_t participant, const std::string& name, const std::string& type);
} // namespace Ros2RawType

/// A topic we read, with its own reader and figures (callbacks on Cyclone's listener thread).
struct Ros2RawReader
{
    std::function<void(const Ros2RawSample&, const dds_sample_info_t&)> onSample;
    dds_entity_t topic = 0;
    dds_entity_t reader = 0;
    std::atomic<int> matched {0};
    std::atomic<quint64> lost {0};

    /// Makes the reader of `topic` with `qos`, samples to onSample from a listener (with
    /// `listen`) or from take() only; false when Cyclone refuses.
    bool open(dds_entity_t participant, const dds_qos_t* qos, bool listen);
    /// Takes at most `max` samples there are now, each to onSample; the number taken.
    int take(int max);
    /// Deletes the reader and the topic (waits for a listener callback in flight).
    void close();
};
