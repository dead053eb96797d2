#pragma once
//! \file byte_codec.h
//! Bounded little helpers for compact binary formats: LEB128 varints with zigzag for signed
//! values, base64url without padding. Readers never read past the end and throw
//! InvalidInputError with what was being read.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace zomeify {

class ByteWriter
{
public:
    void u8(uint8_t x) { bytes_.push_back(x); }
    void varint(uint64_t x);
    void zigzag(int64_t x) { varint((static_cast<uint64_t>(x) << 1) ^ static_cast<uint64_t>(x >> 63)); }
    void f64(double x);
    const std::vector<uint8_t>& bytes() const { return bytes_; }

private:
    std::vector<uint8_t> bytes_;
};

class ByteReader
{
public:
    explicit ByteReader(const std::vector<uint8_t>& bytes) : bytes_(bytes) {}
    uint8_t u8(const char* what);
    uint64_t varint(const char* what);
    int64_t zigzag(const char* what);
    double f64(const char* what);
    size_t left() const { return bytes_.size() - pos_; }
    bool done() const { return pos_ == bytes_.size(); }

private:
    const std::vector<uint8_t>& bytes_;
    size_t pos_ = 0;
};

std::string base64url_encode(const std::vector<uint8_t>& bytes);
//! Throws InvalidInputError on a character outside the base64url alphabet or a bad length.
std::vector<uint8_t> base64url_decode(std::string_view text);

} // namespace zomeify
