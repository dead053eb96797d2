#pragma once
//! \file text_scan.h
//! Line and token scanning shared by the text readers (OBJ, ASCII STL, ASCII PLY, OFF). Works on a
//! byte span without copying, counts lines for messages and rejects control bytes, so a binary file
//! given a text extension fails on its first line instead of being half-read.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace zomeify::detail {

//! Hands out the lines of a text buffer (LF or CRLF), without their line ending.
class LineScanner
{
public:
    explicit LineScanner(std::span<const uint8_t> bytes);

    //! The next line; false at the end. Throws InvalidInputError on NUL or other control bytes.
    bool next(std::string_view& line);
    //! 1-based number of the line last returned.
    size_t line_number() const { return line_number_; }
    //! Lines (counting a last line without a newline) not yet returned.
    size_t remaining_lines() const;

private:
    std::string_view text_;
    size_t pos_ = 0;
    size_t line_number_ = 0;
};

//! Splits one line on blanks (space, tab, vertical tab, form feed).
class TokenSplitter
{
public:
    explicit TokenSplitter(std::string_view line) : line_(line) {}
    //! The next token; false when none is left.
    bool next(std::string_view& token);
    //! Everything after the current position with leading blanks removed.
    std::string_view rest();

private:
    std::string_view line_;
    size_t pos_ = 0;
};

//! Parses a whole token as a decimal or scientific number ("nan" and "inf" parse and are caught by
//! the callers' finiteness checks). False if the token is not entirely a number.
bool parse_double(std::string_view token, double& value);
//! Parses a whole token as a signed 64-bit integer.
bool parse_int(std::string_view token, long long& value);

//! "line 12: " style prefix for messages.
std::string at_line(size_t line_number);

//! The token quoted and shortened for a message, with non-printable bytes shown as '?'.
std::string quote_token(std::string_view token);

} // namespace zomeify::detail
