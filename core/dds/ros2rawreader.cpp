// SPDX-License-Identifier: MIT
#include "dds/ros2rawreader.h"

#include <algorithm>

using namespace eprosima::fastdds::dds;
namespace rtps = eprosima::fastrtps::rtps;

Ros2RawType::Ros2RawType(const std::string& name)
{
    setName(name.c_str());
    m_typeSize = 64; // samples grow as needed: readers use dynamic payloads
    m_isGetKeyDefined = false;
    auto_fill_type_object(false);
    auto_fill_type_information(false);
}

bool Ros2RawType::serialize(void* data, rtps::SerializedPayload_t* payload)
{
    const auto& bytes = static_cast<Ros2RawSample*>(data)->bytes;
    if (bytes.size() < 4 || bytes.size() > payload->max_size)
        return false;
    std::copy(bytes.begin(), bytes.end(), payload->data);
    payload->length = uint32_t(bytes.size());
    payload->encapsulation = (bytes[1] & 1) ? CDR_LE : CDR_BE;
    return true;
}

bool Ros2RawType::deserialize(rtps::SerializedPayload_t* payload, void* data)
{
    if (payload->length > uint32_t(kMaxSampleBytes))
        return false;
    static_cast<Ros2RawSample*>(data)->bytes.assign(payload->data, payload->data + payload->length);
    return true;
}

std::function<uint32_t()> Ros2RawType::getSerializedSizeProvider(void* data)
{
    return [data] { return uint32_t(static_cast<Ros2RawSample*>(data)->bytes.size()); };
}

void* Ros2RawType::createData()
{
    return new Ros2RawSample;
}

void Ros2RawType::deleteData(void* data)
{
    delete static_cast<Ros2RawSample*>(data);
}

void Ros2RawReader::on_data_available(DataReader* r)
{
    Ros2RawSample sample;
    SampleInfo info;
    // bounded: what is there now, not what keeps coming while we take
    for (int i = 0; i < 1000 && r->take_next_sample(&sample, &info) == ReturnCode_t::RETCODE_OK; ++i)
        if (info.valid_data && onSample)
            onSample(sample, info);
}
