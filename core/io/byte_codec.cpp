#include "core/io/byte_codec.h"

#include <cstring>

#include "core/base/errors.h"

namespace zomeify {

namespace {
constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_";

int decode_char(char c)
{
    if (c >= 'A' && c <= 'Z')
        return c - 'A';
    if (c >= 'a' && c <= 'z')
        return c - 'a' + 26;
    if (c >= '0' && c <= '9')
        return c - '0' + 52;
    if (c == '-')
        return 62;
    if (c == '_')
        return 63;
    return -1;
}
} // namespace

void ByteWriter::varint(uint64_t x)
{
    while (x >= 0x80)
    {
        bytes_.push_back(static_cast<uint8_t>(x | 0x80));
        x >>= 7;
    }
    bytes_.push_back(static_cast<uint8_t>(x));
}

void ByteWriter::f64(double x)
{
    uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    for (int i = 0; i < 8; ++i)
        bytes_.push_back(static_cast<uint8_t>(bits >> (8 * i)));
}

uint8_t ByteReader::u8(const char* what)
{
    if (pos_ >= bytes_.size())
        throw InvalidInputError(std::string("the data ends early, while reading ") + what);
    return bytes_[pos_++];
}

uint64_t ByteReader::varint(const char* what)
{
    uint64_t x = 0;
    for (int shift = 0; shift < 64; shift += 7)
    {
        const uint8_t b = u8(what);
        x |= static_cast<uint64_t>(b & 0x7f) << shift;
        if (!(b & 0x80))
            return x;
    }
    throw InvalidInputError(std::string("a number is too long, while reading ") + what);
}

int64_t ByteReader::zigzag(const char* what)
{
    const uint64_t x = varint(what);
    return static_cast<int64_t>(x >> 1) ^ -static_cast<int64_t>(x & 1);
}

double ByteReader::f64(const char* what)
{
    uint64_t bits = 0;
    for (int i = 0; i < 8; ++i)
        bits |= static_cast<uint64_t>(u8(what)) << (8 * i);
    double x;
    std::memcpy(&x, &bits, sizeof x);
    return x;
}

std::string base64url_encode(const std::vector<uint8_t>& bytes)
{
    std::string out;
    out.reserve((bytes.size() * 4 + 2) / 3);
    for (size_t i = 0; i < bytes.size(); i += 3)
    {
        const size_t n = std::min<size_t>(3, bytes.size() - i);
        uint32_t v = static_cast<uint32_t>(bytes[i]) << 16;
        if (n > 1)
            v |= static_cast<uint32_t>(bytes[i + 1]) << 8;
        if (n > 2)
            v |= bytes[i + 2];
        for (size_t k = 0; k < n + 1; ++k)
            out.push_back(kAlphabet[(v >> (18 - 6 * k)) & 63]);
    }
    return out;
}

std::vector<uint8_t> base64url_decode(std::string_view text)
{
    if (text.size() % 4 == 1)
        throw InvalidInputError("the encoded data has an impossible length");
    std::vector<uint8_t> out;
    out.reserve(text.size() * 3 / 4);
    uint32_t acc = 0;
    int bits = 0;
    for (size_t i = 0; i < text.size(); ++i)
    {
        const int d = decode_char(text[i]);
        if (d < 0)
            throw InvalidInputError("unexpected character at position " + std::to_string(i) + " of the encoded data");
        acc = (acc << 6) | static_cast<uint32_t>(d);
        bits += 6;
        if (bits >= 8)
        {
            bits -= 8;
            out.push_back(static_cast<uint8_t>(acc >> bits));
            acc &= (1u << bits) - 1;
        }
    }
    return out;
}

} // namespace zomeify
