#pragma once
//! \file errors.h
//! The exception types of the core. Every user-facing entry point catches these and turns them
//! into a one-line message; nothing else is expected to escape.

#include <stdexcept>
#include <string>

namespace zomeify {

//! Input that is malformed or describes something that is not a valid model (files, links, options).
class InvalidInputError : public std::runtime_error
{
public:
    using std::runtime_error::runtime_error;
};

//! Exact integer arithmetic would overflow (coordinates far outside any buildable model).
class OverflowError : public std::runtime_error
{
public:
    using std::runtime_error::runtime_error;
};

//! A file could not be opened, read or written.
class IoError : public std::runtime_error
{
public:
    using std::runtime_error::runtime_error;
};

} // namespace zomeify
