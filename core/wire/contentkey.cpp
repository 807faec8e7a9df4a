// SPDX-License-Identifier: MIT
#include "contentkey.h"

#include <algorithm>

ContentKey ContentKey::of(QByteArrayView bytes)
{
    ContentKey key;
    key.size = bytes.size();
    key.hash = qHashBits(bytes.data(), size_t(std::min(bytes.size(), kHashedBytes)), 0);
    return key;
}

std::optional<ContentKey> ContentKey::ofPayload(QByteArrayView payload, qsizetype stampBytes)
{
    if (stampBytes < 0 || payload.size() < stampBytes)
        return std::nullopt;
    return of(payload.sliced(stampBytes));
}
