// SPDX-License-Identifier: MIT
#pragma once

// Fast DDS's side of a type-agnostic subscription; included by ros2engine.cpp only, so that
// Fast DDS stays out of every header other layers see.

#include <atomic>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TopicDataType.hpp>
#include <functional>
#include <QtGlobal>
#include <string>
#include <vector>

/// A sample as its CDR bytes, encapsulation header included.
struct Ros2RawSample
{
    std::vector<unsigned char> bytes;
};

/// A type that takes any sample as bytes, whatever its name says (roscpp's ShapeShifter for DDS).
class Ros2RawType : public eprosima::fastdds::dds::TopicDataType
{
public:
    static constexpr int kMaxSampleBytes = 64 * 1024 * 1024;

    explicit Ros2RawType(const std::string& name);
    bool serialize(void* data, eprosima::fastrtps::rtps::SerializedPayload_t* payload) override;
    bool deserialize(eprosima::fastrtps::rtps::SerializedPayload_t* payload, void* data) override;
    std::function<uint32_t()> getSerializedSizeProvider(void* data) override;
    void* createData() override;
    void deleteData(void* data) override;
    bool getKey(void*, eprosima::fastrtps::rtps::InstanceHandle_t*, bool) override { return false; }
};

/// A topic we read, with its own reader and figures (callbacks on Fast DDS's threads).
struct Ros2RawReader : public eprosima::fastdds::dds::DataReaderListener
{
    std::function<void(const Ros2RawSample&, const eprosima::fastdds::dds::SampleInfo&)> onSample;
    eprosima::fastdds::dds::Topic* topic = nullptr;
    eprosima::fastdds::dds::DataReader* reader = nullptr;
    std::atomic<int> matched {0};
    std::atomic<quint64> lost {0};

    void on_data_available(eprosima::fastdds::dds::DataReader* r) override;
    void on_subscription_matched(eprosima::fastdds::dds::DataReader*,
                                 const eprosima::fastdds::dds::SubscriptionMatchedStatus& status) override
    {
        matched = status.current_count;
    }
    void on_sample_lost(eprosima::fastdds::dds::DataReader*,
                        const eprosima::fastdds::dds::SampleLostStatus& status) override
    {
        lost = quint64(status.total_count);
    }
};
