#pragma once
//! \file advisor.h
//! The resolution advisor (issue 4): a number of cells along the longest side at which Z0 is a
//! closed 2-manifold with the genus of S. Genus is not monotone in the resolution (a grid line can
//! fall differently through a thin gap), so resolutions are scanned one by one rather than
//! bisected, over a bounded range: the same answer on every machine (issue 37).

#include <string>
#include <vector>

#include "core/voxel/initial_model.h"

namespace zomeify {

//! The finest grid the hint searches by default: the automatic choice's range (auto_resolution.h);
//! a finer one is still accepted when asked for, and its hint looks a few grids further.
inline constexpr int kAdviceMaxResolution = 32;

struct AdvisorOptions
{
    int min_resolution = 4;                    //!< one end of the scan
    int max_resolution = kAdviceMaxResolution; //!< the other end
    bool downward = false;                     //!< scan from max_resolution down (the nearest coarser grid first)
    //! Retries and cleanup used for every trial (resolution ignored; target_genus is set to the
    //! surface's, so a resolution counts when it or one of its nudged grids keeps the genus).
    InitialModelOptions initial;
};

//! One resolution tried.
struct ResolutionTrial
{
    int resolution = 0;
    bool valid = false;  //!< Z0 is a closed 2-manifold
    long long genus = 0; //!< genus of Z0
    double seconds = 0.0;
    size_t balls = 0;     //!< of Z0
    double size_cm = 0.0; //!< Z0's built longest side (auto_resolution.h's z0_built_size_cm; 0 when not measured)
};

struct AdvisorResult
{
    bool found = false;
    int resolution = 0; //!< the first resolution of the scan keeping the genus (when found)
    long long surface_genus = 0;
    std::vector<ResolutionTrial> trials;
    double seconds = 0.0;
};

//! Resolutions from `lo` to `hi` by distance to `p`: p, p+1, p-1, p+2, p-2, ... (finer first at an
//! equal distance, since a finer grid keeps more of the shape). The order both the automatic choice
//! and the hint search in.
std::vector<int> nearest_first(int p, int lo, int hi);

//! Scans resolutions min..max (or max..min) and stops at the first whose Z0 is valid with genus
//! `surface_genus`.
AdvisorResult advise_resolution(const TriangleMesh& surface, long long surface_genus, const InsidePredicate& inside,
                                const AdvisorOptions& options = {});

//! A one-line explanation for a user whose choice gave Z0 the genus `genus` instead of the
//! surface's, e.g. "at 10 cells the 4 handles of this shape close up; 14 keeps them". When
//! nothing was found, `searched_from`..`searched_to` is the range every grid of which was tried.
std::string advice_message(int resolution, long long genus, const AdvisorResult& advice, int searched_from = 0,
                           int searched_to = 0);

//! The hint for a user whose resolution gave Z0 the genus `genus` instead of the surface's ("" when
//! they agree): the grid nearest theirs that keeps it (nearest_first, from 4 cells to
//! kAdviceMaxResolution or 8 past theirs). Bounded by the grids it may try, never by time. The CLI's
//! summary and the page's estimate both say this.
struct GenusAdvice
{
    std::string message; //!< "" when the genus is kept
    int resolution = 0;  //!< the grid that keeps the genus, 0 when none was found
};
GenusAdvice genus_advice(const TriangleMesh& surface, long long surface_genus, const InsidePredicate& inside,
                         int resolution, long long genus, const InitialModelOptions& initial = {});

} // namespace zomeify
