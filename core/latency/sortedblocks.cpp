// SPDX-License-Identifier: MIT
#include "sortedblocks.h"

#include <algorithm>

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
    std::size_t i = std::size_t(std::lower_bound(m_maxes.begin(), m_maxes.end(), value) - m_maxes.begin());
    if (i == m_blocks.size())
        i = m_blocks.size() - 1;
    std::vector<qint64>& block = m_blocks[i];
    block.insert(std::upper_bound(block.begin(), block.end(), value), value);
    m_maxes[i] = block.back();
    if (block.size() > kMaxBlock) {
        std::vector<qint64> upper(block.begin() + std::ptrdiff_t(block.size() / 2), block.end());
        block.resize(block.size() / 2);
        m_maxes[i] = block.back();
        m_maxes.insert(m_maxes.begin() + std::ptrdiff_t(i) + 1, upper.back());
        m_blocks.insert(m_blocks.begin() + std::ptrdiff_t(i) + 1, std::move(upper));
    }
}

bool SortedBlocks::erase(qint64 value)
{
    const std::size_t i
        = std::size_t(std::lower_bound(m_maxes.begin(), m_maxes.end(), value) - m_maxes.begin());
    if (i == m_blocks.size())
        return false;
    std::vector<qint64>& block = m_blocks[i];
    const auto it = std::lower_bound(block.begin(), block.end(), value);
    if (it == block.end() || *it != value)
        return false;
    block.erase(it);
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
    const std::size_t i
        = std::size_t(std::upper_bound(m_prefix.begin(), m_prefix.end(), k) - m_prefix.begin()) - 1;
    return m_blocks[i][std::size_t(k - m_prefix[i])];
}

qint64 SortedBlocks::countBelow(qint64 value) const
{
    const std::size_t i
        = std::size_t(std::lower_bound(m_maxes.begin(), m_maxes.end(), value) - m_maxes.begin());
    if (i == m_blocks.size())
        return m_size;
    updatePrefix();
    const std::vector<qint64>& b = m_blocks[i];
    return m_prefix[i] + (std::lower_bound(b.begin(), b.end(), value) - b.begin());
}

qint64 SortedBlocks::countAtMost(qint64 value) const
{
    const std::size_t i
        = std::size_t(std::upper_bound(m_maxes.begin(), m_maxes.end(), value) - m_maxes.begin());
    if (i == m_blocks.size())
        return m_size;
    updatePrefix();
    const std::vector<qint64>& b = m_blocks[i];
    return m_prefix[i] + (std::upper_bound(b.begin(), b.end(), value) - b.begin());
}

std::vector<qint64> SortedBlocks::toVector() const
{
    std::vector<qint64> out;
    out.reserve(std::size_t(m_size));
    for (const std::vector<qint64>& b : m_blocks)
        out.insert(out.end(), b.begin(), b.end());
    return out;
}
