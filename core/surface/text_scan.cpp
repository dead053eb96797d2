#include "core/surface/text_scan.h"

#include <array>
#include <charconv>
#include <cstdlib>
#include <cstring>

#include "core/base/errors.h"

namespace zomeify::detail {

namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }

} // namespace

LineScanner::LineScanner(std::span<const uint8_t> bytes)
    : text_(reinterpret_cast<const char*>(bytes.data()), bytes.size())
{
}

bool LineScanner::next(std::string_view& line)
{
    if (pos_ >= text_.size())
        return false;
    size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos)
        end = text_.size();
    line = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    ++line_number_;
    if (!line.empty() && line.back() == '\r')
        line.remove_suffix(1);
    // Text formats never contain control bytes; finding one means the file is binary (a PNG renamed
    // .obj, random bytes), and saying so is clearer than a parse error further down.
    for (const char c : line)
    {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 && !is_blank(c))
            throw InvalidInputError(at_line(line_number_) + "binary data in a text file");
    }
    return true;
}

size_t LineScanner::remaining_lines() const
{
    if (pos_ >= text_.size())
        return 0;
    const std::string_view rest = text_.substr(pos_);
    size_t lines = 0;
    for (const char c : rest)
        lines += c == '\n';
    return lines + (rest.back() != '\n');
}

bool TokenSplitter::next(std::string_view& token)
{
    while (pos_ < line_.size() && is_blank(line_[pos_]))
        ++pos_;
    if (pos_ >= line_.size())
        return false;
    const size_t start = pos_;
    while (pos_ < line_.size() && !is_blank(line_[pos_]))
        ++pos_;
    token = line_.substr(start, pos_ - start);
    return true;
}

std::string_view TokenSplitter::rest()
{
    while (pos_ < line_.size() && is_blank(line_[pos_]))
        ++pos_;
    return line_.substr(pos_);
}

bool parse_double(std::string_view token, double& value)
{
    // Floating-point from_chars is missing from Emscripten 3.1.6's libc++, so strtod on a bounded
    // NUL-terminated copy (the C locale's decimal point is '.', as the formats require).
    std::array<char, 64> buffer{};
    if (token.empty() || token.size() >= buffer.size())
        return false;
    std::memcpy(buffer.data(), token.data(), token.size());
    char* end = nullptr;
    value = std::strtod(buffer.data(), &end);
    return end == buffer.data() + token.size();
}

bool parse_int(std::string_view token, long long& value)
{
    const char* first = token.data();
    const char* last = token.data() + token.size();
    if (first != last && *first == '+')
        ++first;
    const auto result = std::from_chars(first, last, value);
    return first != last && result.ec == std::errc() && result.ptr == last;
}

std::string at_line(size_t line_number) { return "line " + std::to_string(line_number) + ": "; }

std::string quote_token(std::string_view token)
{
    // Built with append: GCC 12 warns falsely (-Wrestrict) on "'" + std::string(...).
    constexpr size_t max_shown = 24;
    std::string s(1, '\'');
    // Bytes outside printable ASCII would garble a one-line terminal message.
    for (const char c : token.substr(0, max_shown))
        s.push_back(c >= 0x20 && c < 0x7F ? c : '?');
    if (token.size() > max_shown)
        s.append("...");
    s.push_back('\'');
    return s;
}

} // namespace zomeify::detail
