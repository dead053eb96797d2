#include "wasm/run_options.h"

namespace zomeify::web {

int max_run_threads()
{
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
    return 1;
#elif defined(ZOME_WEB_POOL_SIZE)
    // One pool worker runs the pipeline and is itself annealing thread 0; one more stays spare.
    return ZOME_WEB_POOL_SIZE - 1;
#else
    return 4;
#endif
}

} // namespace zomeify::web
