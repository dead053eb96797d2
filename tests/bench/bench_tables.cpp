// Lookup-table construction: time (median of repeated fresh builds) and memory held.
// Prints one JSON object.
#include <iostream>

#include <nlohmann/json.hpp>

#include "core/zome/slots.h"
#include "core/zome/symmetry.h"
#include "core/zome/tables.h"
#include "tests/bench/bench_util.h"

using namespace zomeify;

int main()
{
    // The first use also builds the 186-vector index and the rotations: time that separately.
    Stopwatch first;
    const ZomeTables& shared = ZomeTables::get();
    const double first_use_s = first.seconds();
    Stopwatch rot;
    const size_t rotations = zome_rotations().size();
    const double rotations_s = rot.seconds();

    size_t bytes = 0;
    const double build_s = bench::median_seconds(9, [&] { bytes = ZomeTables::build()->memory_bytes(); });
    const nlohmann::json out = {
        {"bench", "tables"},
        {"platform", bench::platform()},
        {"tables_build_ms_median", build_s * 1e3},
        {"tables_first_use_ms", first_use_s * 1e3},
        {"rotations_search_ms", rotations_s * 1e3},
        {"tables_bytes", bytes},
        {"split_total", shared.split_total()},
        {"merge_keys", shared.merge_keys()},
        {"change_total", shared.change_total()},
        {"rotations", rotations},
        {"peak_memory_mib", bench::peak_memory_mib()},
    };
    std::cout << out.dump() << std::endl;
    return 0;
}
