#pragma once
//! \file advisor.h
//! The resolution advisor (issue 4): the smallest number of cells along the longest side at which
//! Z0 is a closed 2-manifold with the genus of S. Genus is not monotone in the resolution (a grid
//! line can fall differently through a thin gap), so resolutions are scanned upward, within a
//! budget, rather than bisected.

#include <string>
#include <vector>

#include "core/voxel/initial_model.h"

namespace zomeify {

//! The finest grid the advice and the automatic resolution search by default (run_settings.h
//! gives it to the page); a finer one is still accepted when asked for.
inline constexpr int kAdviceMaxResolution = 64;

struct AdvisorOptions
{
    int min_resolution = 4;                    //!< first resolution scanned
    int max_resolution = kAdviceMaxResolution; //!< last resolution scanned
    double seconds = 20.0;                     //!< wall-time budget; the scan stops after the trial that exceeds it
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
};

struct AdvisorResult
{
    bool found = false;
    int resolution = 0; //!< the smallest resolution keeping the genus (when found)
    long long surface_genus = 0;
    std::vector<ResolutionTrial> trials;
    double seconds = 0.0;
};

//! Scans resolutions min..max and stops at the first whose Z0 is valid with genus `surface_genus`.
AdvisorResult advise_resolution(const TriangleMesh& surface, long long surface_genus, const InsidePredicate& inside,
                                const AdvisorOptions& options = {});

//! A one-line explanation for a user whose choice gave Z0 the genus `genus` instead of the
//! surface's, e.g. "at 10 cells the 4 handles of this shape close up; 14 keeps them".
std::string advice_message(int resolution, long long genus, const AdvisorResult& advice);

//! The hint for a user whose resolution gave Z0 the genus `genus` instead of the surface's ("" when
//! they agree): the nearest finer grid that keeps it, else a coarser one, searched for at most
//! `seconds`. The CLI's summary and the page's estimate both say this.
struct GenusAdvice
{
    std::string message; //!< "" when the genus is kept
    int resolution = 0;  //!< the grid that keeps the genus, 0 when none was found
};
GenusAdvice genus_advice(const TriangleMesh& surface, long long surface_genus, const InsidePredicate& inside,
                         int resolution, long long genus, double seconds);

} // namespace zomeify
