#pragma once
//! \file args.h
//! A small command-line reader: positional arguments, repeatable "-o X" style options and flags.
//! Unknown options are errors (a typo must not silently run with defaults).

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace zomeify::cli {

class Args
{
public:
    //! Parses argv (after the command name). `valued` lists the options that take a value,
    //! `flags` the ones that do not. Throws InvalidInputError on anything else.
    Args(const std::vector<std::string>& argv, const std::set<std::string>& valued, const std::set<std::string>& flags);

    const std::vector<std::string>& positional() const { return positional_; }
    bool has(const std::string& name) const;
    std::optional<std::string> value(const std::string& name) const;
    std::vector<std::string> values(const std::string& name) const;
    //! The value as a number in [lo, hi], or `fallback` when absent; a clear error otherwise.
    double number(const std::string& name, double fallback, double lo, double hi) const;
    long long integer(const std::string& name, long long fallback, long long lo, long long hi) const;
    //! Exactly `n` positional arguments named `what` (for the error message).
    void expect_positional(size_t n, const std::string& what) const;

private:
    std::vector<std::string> positional_;
    std::map<std::string, std::vector<std::string>> options_;
};

} // namespace zomeify::cli
