#include "wasm/run_options.h"

#include <algorithm>

#if defined(__EMSCRIPTEN_PTHREADS__)
#include <emscripten/threading.h>
#endif

namespace zomeify::web {

int max_run_threads()
{
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
    return 1;
#elif defined(__EMSCRIPTEN_PTHREADS__)
    // As many as the browser reports cores, 2 to 16: the pool (wasm/CMakeLists.txt,
    // ZOME_WEB_POOL_SIZE) holds one worker more, so every annealing thread starts at once (one
    // pool worker runs the pipeline and is itself annealing thread 0; one stays spare).
    return std::clamp(emscripten_num_logical_cores(), 2, 16);
#else
    return 4;
#endif
}

} // namespace zomeify::web
