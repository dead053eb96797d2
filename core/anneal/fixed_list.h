#pragma once
//! \file fixed_list.h
//! FixedList: a list with inline storage of a fixed capacity that never allocates and never throws.
//! The annealer's per-proposal descriptions (LocalChange) are built millions of times per second by
//! every thread; a full list refuses further elements and remembers that it overflowed, so the
//! caller can reject the proposal instead of paying for a heap fallback.

#include <array>
#include <cstddef>

namespace zomeify {

template <class T, size_t N>
class FixedList
{
public:
    //! Appends `value`; returns false (and sets overflowed()) when the list is full.
    bool push_back(const T& value) noexcept
    {
        if (size_ == N)
        {
            overflowed_ = true;
            return false;
        }
        items_[size_++] = value;
        return true;
    }
    //! Empties the list and clears the overflow flag.
    void clear() noexcept
    {
        size_ = 0;
        overflowed_ = false;
    }
    //! Whether a push_back was refused since the last clear().
    bool overflowed() const noexcept { return overflowed_; }
    static constexpr size_t capacity() noexcept { return N; }
    size_t size() const noexcept { return size_; }
    bool empty() const noexcept { return size_ == 0; }
    const T& operator[](size_t i) const noexcept { return items_[i]; }
    T& operator[](size_t i) noexcept { return items_[i]; }
    const T* begin() const noexcept { return items_.data(); }
    const T* end() const noexcept { return items_.data() + size_; }

private:
    std::array<T, N> items_{};
    size_t size_ = 0;
    bool overflowed_ = false;
};

} // namespace zomeify
