#pragma once
//! \file topology_error.h
//! The error of a mesh edit or build that would break the halfedge structure (a non-manifold
//! vertex or edge, a face that cannot be linked in). Conversions from user data turn it into
//! InvalidInputError; inside the annealer it signals a bug, since operators check before acting.

#include <stdexcept>

namespace zomeify {

class TopologyError : public std::runtime_error
{
public:
    using std::runtime_error::runtime_error;
};

} // namespace zomeify
