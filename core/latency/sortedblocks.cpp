// SPDX-License-Identifier: MIT
#include "sortedblocks.h"

#include <algorithm>
#include <cstring>

namespace {
// Branch-free binary searches: on random latencies the comparisons of std::lower_bound are coin
// flips the branch predictor loses; a conditional move does not care.
std::size_t lowerBound(const qint64* data, std::size_t n, qint64 value)
{
    if (n == 0)
        return 0;
    const qint64* base = data;
    while (n > 1) {
        const std::size_t half = n / 2;
        base += half & (std::size_t(0) - std::size_t(base[half - 1] < value));
        n -= half;
    }
    return std::size_t(base - data) + (*base < value);
}

std::size_t upperBound(const qint64* data, std::size_t n, qint64 value)
{
    if (n == 0)
        return 0;
    const qint64* base = data;
    while (n > 1) {
        const std::size_t half = n / 2;
        base += half & (std::size_t(0) - std::size_t(base[half - 1] <= value));
        n -= half;
    }
    return std::size_t(base - data) + (*base <= value);
}

std::size_t lowerBound(const std::vector<qint64>& v, qint64 value)
{
    return lowerBound(v.data(), v.size(), value);
}

std::size_t upperBound(const std::vector<qint64>& v, qint64 value)
{
    return upperBound(v.data(), v.size(), value);
}
} // namespace

void SortedBlocks::insert(qint64 value)
{
    ++m_size;
    m_prefixDirty = true;
    if (m_blocks.empty()) {
        m_blocks.emplace_back(1, value);
        m_blocks.back().reserve(kMaxBlock / 2);
        m_maxes.push_back(value);
        return;
    }
    std::size_t i = lowerBound(m_maxes, value);
    if (i == m_blocks.size())
        i = m_blocks.size() - 1;
    std::vector<qint64>& block = m_blocks[i];
    block.insert(block.begin() + std::ptrdiff_t(upperBound(block, value)), value);
    m_maxes[i] = block.back();
    if (block.size() > kMaxBlock) {
        std::vector<qint64> upper(block.begin() + std::ptrdiff_t(block.size() / 2), block.end());
        block.resize(block.size() / 2);
        m_maxes[i] = block.back();
        m_maxes.insert(m_maxes.begin() + std::ptrdiff_t(i) + 1, upper.back());
        m_blocks.insert(m_blocks.begin() + std::ptrdiff_t(i) + 1, std::move(upper));
    }
}

bool SortedBlocks::replace(qint64 out, qint64 in)
{
    const std::size_t i = lowerBound(m_maxes, out);
    if (i == m_blocks.size())
        return false;
    std::vector<qint64>& block = m_blocks[i];
    const std::size_t from = lowerBound(block, out);
    if (from == block.size() || block[from] != out)
        return false;
    // Does `in` belong in this block, with `out` gone? Between the previous block's max and the
    // next block's first value.
    const bool fits
        = (i == 0 || m_maxes[i - 1] <= in) && (i + 1 == m_blocks.size() || in <= m_blocks[i + 1].front());
    if (!fits) {
        erase(out);
        insert(in);
        return true;
    }
    qint64* d = block.data();
    if (in >= out) {
        // Shift the values in (out, in] one place left, then put `in` after them.
        const std::size_t to = upperBound(block, in) - 1;
        std::memmove(d + from, d + from + 1, (to - from) * sizeof(qint64));
        d[to] = in;
    } else {
        const std::size_t to = upperBound(d, from, in);
        std::memmove(d + to + 1, d + to, (from - to) * sizeof(qint64));
        d[to] = in;
    }
    m_maxes[i] = block.back();
    return true; // sizes unchanged: the prefix counts stay valid
}

bool SortedBlocks::erase(qint64 value)
{
    const std::size_t i = lowerBound(m_maxes, value);
    if (i == m_blocks.size())
        return false;
    std::vector<qint64>& block = m_blocks[i];
    const std::size_t at = lowerBound(block, value);
    if (at == block.size() || block[at] != value)
        return false;
    block.erase(block.begin() + std::ptrdiff_t(at));
    --m_size;
    m_prefixDirty = true;
    if (block.empty()) {
        removeBlock(i);
        return true;
    }
    m_maxes[i] = block.back();
    // Keep blocks from thinning out: merge a small block into its right neighbour.
    if (block.size() < kMaxBlock / 4 && i + 1 < m_blocks.size()
        && block.size() + m_blocks[i + 1].size() <= kMaxBlock) {
        std::vector<qint64>& next = m_blocks[i + 1];
        next.insert(next.begin(), block.begin(), block.end());
        removeBlock(i);
    }
    return true;
}

void SortedBlocks::removeBlock(std::size_t i)
{
    m_blocks.erase(m_blocks.begin() + std::ptrdiff_t(i));
    m_maxes.erase(m_maxes.begin() + std::ptrdiff_t(i));
}

void SortedBlocks::clear()
{
    m_blocks.clear();
    m_maxes.clear();
    m_prefix.clear();
    m_prefixDirty = false;
    m_size = 0;
}

void SortedBlocks::updatePrefix() const
{
    if (!m_prefixDirty && m_prefix.size() == m_blocks.size())
        return;
    m_prefix.resize(m_blocks.size());
    qint64 n = 0;
    for (std::size_t i = 0; i < m_blocks.size(); ++i) {
        m_prefix[i] = n;
        n += qint64(m_blocks[i].size());
    }
    m_prefixDirty = false;
}

qint64 SortedBlocks::at(qint64 k) const
{
    updatePrefix();
    const std::size_t i = upperBound(m_prefix, k) - 1;
    return m_blocks[i][std::size_t(k - m_prefix[i])];
}

std::pair<qint64, qint64> SortedBlocks::atPair(qint64 k) const
{
    updatePrefix();
    const std::size_t i = upperBound(m_prefix, k) - 1;
    const std::vector<qint64>& block = m_blocks[i];
    const std::size_t j = std::size_t(k - m_prefix[i]);
    if (j + 1 < block.size())
        return {block[j], block[j + 1]};
    if (i + 1 < m_blocks.size())
        return {block[j], m_blocks[i + 1].front()};
    return {block[j], block[j]};
}

qint64 SortedBlocks::countBelow(qint64 value) const
{
    const std::size_t i = lowerBound(m_maxes, value);
    if (i == m_blocks.size())
        return m_size;
    updatePrefix();
    return m_prefix[i] + qint64(lowerBound(m_blocks[i], value));
}

qint64 SortedBlocks::countAtMost(qint64 value) const
{
    const std::size_t i = upperBound(m_maxes, value);
    if (i == m_blocks.size())
        return m_size;
    updatePrefix();
    return m_prefix[i] + qint64(upperBound(m_blocks[i], value));
}

std::vector<qint64> SortedBlocks::toVector() const
{
    std::vector<qint64> out;
    out.reserve(std::size_t(m_size));
    for (const std::vector<qint64>& b : m_blocks)
        out.insert(out.end(), b.begin(), b.end());
    return out;
}
