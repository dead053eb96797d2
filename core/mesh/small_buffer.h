#pragma once
//! \file small_buffer.h
//! detail::SmallBuffer: a vector with inline storage for the first N elements. Mesh edits collect
//! the halfedges of one face or one vertex star; those are almost always short, and the annealer
//! performs millions of edits, so the common case must not touch the heap.

#include <array>
#include <cstddef>
#include <vector>

namespace zomeify::detail {

template <class T, size_t N>
class SmallBuffer
{
public:
    void push_back(const T& value)
    {
        if (size_ < N)
            inline_[size_] = value;
        else
        {
            if (size_ == N)
                heap_.assign(inline_.begin(), inline_.end());
            heap_.push_back(value);
        }
        ++size_;
    }
    //! Grows or shrinks to n elements (new ones value-initialized).
    void resize(size_t n)
    {
        if (n > N)
        {
            if (size_ <= N)
                heap_.assign(inline_.begin(), inline_.begin() + static_cast<std::ptrdiff_t>(size_));
            heap_.resize(n);
        }
        else
        {
            if (size_ > N)
                for (size_t i = 0; i < n; ++i)
                    inline_[i] = heap_[i];
            for (size_t i = size_; i < n; ++i)
                inline_[i] = T();
        }
        size_ = n;
    }
    void clear()
    {
        size_ = 0;
        heap_.clear();
    }
    size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    T& operator[](size_t i) { return size_ <= N ? inline_[i] : heap_[i]; }
    const T& operator[](size_t i) const { return size_ <= N ? inline_[i] : heap_[i]; }
    T* data() { return size_ <= N ? inline_.data() : heap_.data(); }
    const T* data() const { return size_ <= N ? inline_.data() : heap_.data(); }
    T* begin() { return data(); }
    T* end() { return data() + size_; }
    const T* begin() const { return data(); }
    const T* end() const { return data() + size_; }

private:
    std::array<T, N> inline_{};
    std::vector<T> heap_;
    size_t size_ = 0;
};

} // namespace zomeify::detail
