#include "core/mesh/handles.h"

#include <ostream>

namespace zomeify {

namespace {

// One formatter for all four kinds so invalid handles print the same way everywhere.
std::ostream& print_handle(std::ostream& os, char prefix, MeshIndex idx)
{
    os << prefix;
    if (idx == kInvalidMeshIndex)
        return os << '-';
    return os << idx;
}

} // namespace

std::ostream& operator<<(std::ostream& os, Vertex v) { return print_handle(os, 'v', v.idx()); }
std::ostream& operator<<(std::ostream& os, Halfedge h) { return print_handle(os, 'h', h.idx()); }
std::ostream& operator<<(std::ostream& os, Edge e) { return print_handle(os, 'e', e.idx()); }
std::ostream& operator<<(std::ostream& os, Face f) { return print_handle(os, 'f', f.idx()); }

} // namespace zomeify
