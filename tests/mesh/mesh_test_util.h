#pragma once
//! \file mesh_test_util.h
//! Small helpers shared by the mesh tests.

#include <gtest/gtest.h>

#include "core/mesh/validate.h"

namespace zomeify::test {

//! Options for meshes under construction: open, any valence, bowties allowed to be reported.
inline ValidateOptions open_options()
{
    ValidateOptions o;
    o.require_closed = false;
    o.min_valence = 0;
    return o;
}

//! A gtest assertion result carrying the validator's message.
template <class Mesh>
::testing::AssertionResult is_valid(const Mesh& mesh, const ValidateOptions& options = {})
{
    const ValidationReport r = validate(mesh, options);
    if (r.ok())
        return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << r.message();
}

} // namespace zomeify::test
