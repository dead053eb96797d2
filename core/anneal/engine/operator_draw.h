#pragma once
//! \file operator_draw.h
//! Which operator a step proposes: drawn with AnnealOptions::operator_weights. Equal weights draw
//! with one `below(7)`, so the random stream (and the determinism golden) is the paper's uniform draw.

#include <array>
#include <cstdint>
#include <stdexcept>

#include "core/anneal/proposal.h"
#include "core/anneal/random.h"

namespace zomeify {

class OperatorDraw
{
public:
    //! Throws std::invalid_argument if every weight is 0.
    explicit OperatorDraw(const std::array<uint32_t, kOperatorKinds>& weights)
    {
        uint64_t total = 0;
        bool uniform = true;
        for (int k = 0; k < kOperatorKinds; ++k)
        {
            total += weights[k];
            cumulative_[k] = total;
            uniform = uniform && weights[k] == weights[0];
        }
        if (total == 0)
            throw std::invalid_argument("operator weights are all zero");
        uniform_ = uniform;
        total_ = total;
    }

    OperatorKind draw(Rng& rng) const noexcept
    {
        if (uniform_)
            return static_cast<OperatorKind>(rng.below(kOperatorKinds));
        const uint64_t r = rng.below(total_);
        int k = 0;
        while (r >= cumulative_[k])
            ++k;
        return static_cast<OperatorKind>(k);
    }

private:
    std::array<uint64_t, kOperatorKinds> cumulative_{};
    uint64_t total_ = 0;
    bool uniform_ = true;
};

} // namespace zomeify
