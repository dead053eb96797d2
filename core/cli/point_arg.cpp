#include "core/cli/point_arg.h"

#include <sstream>

#include "core/base/errors.h"

namespace zomeify::cli {

Vec3 point_of(const std::string& text, const std::string& flag)
{
    Vec3 p;
    std::istringstream in(text);
    char comma = 0;
    if (!(in >> p[0] >> comma) || comma != ',' || !(in >> p[1] >> comma) || comma != ',' || !(in >> p[2]) ||
        !(in >> std::ws).eof() || !p.allFinite())
        throw InvalidInputError(flag + " wants a point X,Y,Z in mesh units, got '" + text + "'");
    return p;
}

} // namespace zomeify::cli
