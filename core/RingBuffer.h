// A fixed-capacity ring of values addressed by absolute index.
//
// Every value ever pushed gets the next absolute index (0, 1, 2, ...); the
// ring keeps the newest capacity() of them. Readers remember the absolute
// index they want next, so they can tell exactly how many values were
// overwritten before they came back (overrun accounting), and no index is
// ever reused. Not thread-safe: LiveBuffer adds the lock.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

namespace tactiscope::core {

template <typename T>
class RingBuffer {
public:
    explicit RingBuffer(std::size_t capacity)
        : m_storage(capacity)
    {
        if (capacity == 0) throw std::invalid_argument("RingBuffer capacity must be positive");
    }

    std::size_t capacity() const { return m_storage.size(); }
    std::size_t size() const { return static_cast<std::size_t>(m_written - oldestIndex()); }
    bool empty() const { return m_written == 0; }

    // Absolute index the next pushed value will get; equals the number of
    // values ever pushed.
    std::uint64_t endIndex() const { return m_written; }
    // Absolute index of the oldest value still held.
    std::uint64_t oldestIndex() const { return m_written > capacity() ? m_written - capacity() : 0; }

    void push(const T& value)
    {
        m_storage[slot(m_written)] = value;
        ++m_written;
    }

    void push(std::span<const T> values)
    {
        // Only the newest capacity() values can survive; skip the rest but
        // still account for them in the absolute index.
        if (values.size() > capacity()) {
            m_written += values.size() - capacity();
            values = values.last(capacity());
        }
        std::size_t first = slot(m_written);
        const std::size_t head = std::min(values.size(), capacity() - first);
        std::copy_n(values.begin(), head, m_storage.begin() + static_cast<std::ptrdiff_t>(first));
        std::copy(values.begin() + static_cast<std::ptrdiff_t>(head), values.end(), m_storage.begin());
        m_written += values.size();
    }

    // Value at an absolute index in [oldestIndex(), endIndex()).
    const T& at(std::uint64_t index) const
    {
        if (index < oldestIndex() || index >= m_written) throw std::out_of_range("RingBuffer index not held");
        return m_storage[slot(index)];
    }

    // Copies values with absolute indices [from, from + out.size()) into out.
    // The range must be held: from >= oldestIndex() and the end <= endIndex().
    void copy(std::uint64_t from, std::span<T> out) const
    {
        if (from < oldestIndex() || from + out.size() > m_written) throw std::out_of_range("RingBuffer range not held");
        const std::size_t first = slot(from);
        const std::size_t head = std::min(out.size(), capacity() - first);
        std::copy_n(m_storage.begin() + static_cast<std::ptrdiff_t>(first), head, out.begin());
        std::copy_n(m_storage.begin(), out.size() - head, out.begin() + static_cast<std::ptrdiff_t>(head));
    }

    void clear() { m_written = 0; }
    // Pushes `value` until endIndex() is `end` (at most capacity() of them
    // are held): a ring begun late, aligned with others.
    void fillTo(std::uint64_t end, const T& value)
    {
        if (end <= m_written) return;
        m_written = std::max(m_written, end - std::min<std::uint64_t>(end, capacity()));
        while (m_written < end) push(value);
    }

private:
    std::size_t slot(std::uint64_t index) const { return static_cast<std::size_t>(index % capacity()); }

    std::vector<T> m_storage;
    std::uint64_t m_written = 0;
};

}  // namespace tactiscope::core
