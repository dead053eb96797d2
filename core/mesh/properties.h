#pragma once
//! \file properties.h
//! Typed, named per-element property arrays (style.md §7 rule 2). Each element kind of a mesh owns
//! one PropertyContainer; every array in it always has one entry per element (live or deleted), so
//! adding an element, or compacting in garbage_collection(), touches all arrays at once. Names use
//! the prefixes v:, h:, e: and f:. Handles returned by add/get stay valid until the property is
//! removed or the container is copied. Not thread-safe for add/remove; element access is plain
//! array access and may run concurrently on distinct elements.

#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/mesh/handles.h"

namespace zomeify {

//! The type-erased interface of one property array.
class BasePropertyArray
{
public:
    explicit BasePropertyArray(std::string name) : name_(std::move(name)) {}
    virtual ~BasePropertyArray() = default;
    BasePropertyArray(const BasePropertyArray&) = default;
    BasePropertyArray& operator=(const BasePropertyArray&) = delete;

    //! The property's name, e.g. "v:zpos".
    const std::string& name() const { return name_; }

    virtual void reserve(size_t n) = 0;
    virtual void resize(size_t n) = 0;
    //! Appends one entry holding the default value.
    virtual void push_back() = 0;
    //! Sets entry i back to the default value (a recycled slot).
    virtual void reset(size_t i) = 0;
    //! Keeps entries kept[0], kept[1], ... (strictly increasing old indices) as the new 0, 1, ...
    virtual void compact(const std::vector<MeshIndex>& kept) = 0;
    virtual std::unique_ptr<BasePropertyArray> clone() const = 0;

private:
    std::string name_;
};

//! One property array of element type T.
template <class T>
class PropertyArray final : public BasePropertyArray
{
    // std::vector<bool> packs bits, so distinct elements would share bytes: a data race for the
    // annealer's threads. Use uint8_t for flags.
    static_assert(!std::is_same_v<T, bool>, "use uint8_t instead of bool for mesh properties");

public:
    PropertyArray(std::string name, T default_value)
        : BasePropertyArray(std::move(name)), default_(std::move(default_value))
    {
    }

    void reserve(size_t n) override { data_.reserve(n); }
    void resize(size_t n) override { data_.resize(n, default_); }
    void push_back() override { data_.push_back(default_); }
    void reset(size_t i) override { data_[i] = default_; }
    void compact(const std::vector<MeshIndex>& kept) override
    {
        for (size_t i = 0; i < kept.size(); ++i)
            if (kept[i] != i)
                data_[i] = std::move(data_[kept[i]]);
        data_.resize(kept.size());
    }
    std::unique_ptr<BasePropertyArray> clone() const override { return std::make_unique<PropertyArray<T>>(*this); }

    std::vector<T>& vector() { return data_; }
    const std::vector<T>& vector() const { return data_; }
    const T& default_value() const { return default_; }

private:
    std::vector<T> data_;
    T default_;
};

//! A typed reference to a property array, indexed by the handle type H.
template <class H, class T>
class Property
{
public:
    Property() = default;
    explicit Property(PropertyArray<T>* array) : array_(array) {}

    bool is_valid() const { return array_ != nullptr; }
    const std::string& name() const { return array_->name(); }

    T& operator[](H h) { return array_->vector()[h.idx()]; }
    const T& operator[](H h) const { return array_->vector()[h.idx()]; }

    //! The underlying array (one entry per element, deleted ones included).
    std::vector<T>& vector() { return array_->vector(); }
    const std::vector<T>& vector() const { return array_->vector(); }

    PropertyArray<T>* array() const { return array_; }

private:
    PropertyArray<T>* array_ = nullptr;
};

template <class T>
using VertexProperty = Property<Vertex, T>;
template <class T>
using HalfedgeProperty = Property<Halfedge, T>;
template <class T>
using EdgeProperty = Property<Edge, T>;
template <class T>
using FaceProperty = Property<Face, T>;

//! All property arrays of one element kind, kept at a common size.
class PropertyContainer
{
public:
    PropertyContainer() = default;
    PropertyContainer(const PropertyContainer& other) { *this = other; }
    PropertyContainer& operator=(const PropertyContainer& other)
    {
        if (this == &other)
            return *this;
        arrays_.clear();
        for (const auto& a : other.arrays_)
            arrays_.push_back(a->clone());
        size_ = other.size_;
        return *this;
    }
    PropertyContainer(PropertyContainer&&) noexcept = default;
    PropertyContainer& operator=(PropertyContainer&&) noexcept = default;

    //! Number of elements (every array has this many entries).
    size_t size() const { return size_; }

    //! Adds a property; throws std::invalid_argument if the name is taken.
    template <class T>
    PropertyArray<T>* add(const std::string& name, T default_value = T())
    {
        if (find(name) != nullptr)
            throw std::invalid_argument("mesh property already exists: " + name);
        auto array = std::make_unique<PropertyArray<T>>(name, std::move(default_value));
        array->resize(size_);
        PropertyArray<T>* raw = array.get();
        arrays_.push_back(std::move(array));
        return raw;
    }

    //! The property of that name and type, or nullptr.
    template <class T>
    PropertyArray<T>* get(const std::string& name) const
    {
        return dynamic_cast<PropertyArray<T>*>(find(name));
    }

    //! Whether a property of that name exists (of any type).
    bool exists(const std::string& name) const { return find(name) != nullptr; }

    //! Removes the array (handles to it dangle afterwards).
    void remove(const BasePropertyArray* array)
    {
        for (auto it = arrays_.begin(); it != arrays_.end(); ++it)
            if (it->get() == array)
            {
                arrays_.erase(it);
                return;
            }
    }

    //! The names of all arrays, in creation order.
    std::vector<std::string> names() const
    {
        std::vector<std::string> out;
        for (const auto& a : arrays_)
            out.push_back(a->name());
        return out;
    }

    void reserve(size_t n)
    {
        for (auto& a : arrays_)
            a->reserve(n);
    }
    void resize(size_t n)
    {
        for (auto& a : arrays_)
            a->resize(n);
        size_ = n;
    }
    void push_back()
    {
        for (auto& a : arrays_)
            a->push_back();
        ++size_;
    }
    //! Every array's entry i back to its default (a recycled element slot).
    void reset(size_t i)
    {
        for (auto& a : arrays_)
            a->reset(i);
    }
    void compact(const std::vector<MeshIndex>& kept)
    {
        for (auto& a : arrays_)
            a->compact(kept);
        size_ = kept.size();
    }
    void clear()
    {
        arrays_.clear();
        size_ = 0;
    }

private:
    BasePropertyArray* find(const std::string& name) const
    {
        for (const auto& a : arrays_)
            if (a->name() == name)
                return a.get();
        return nullptr;
    }

    std::vector<std::unique_ptr<BasePropertyArray>> arrays_;
    size_t size_ = 0;
};

} // namespace zomeify
