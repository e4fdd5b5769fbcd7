// What an interruption does (docs/reliability.md, "Interruption"): SIGINT, SIGTERM and SIGHUP
// are handled by one thread that waits for them; it removes every registered temporary
// (materials/core/temporary_files.h) and then ends the process by the same signal, so the
// shell still sees an interruption (exit status 128 + signal). A commit in progress (which
// holds deferInterruptions()) completes first, so the outputs are the old set or the new one.
//
// SIGXFSZ (a file-size limit, `ulimit -f`) is ignored: the write that crosses the limit then
// fails with EFBIG and is reported like a full disk, with the temporaries removed, instead of
// killing the process with a half-written file beside the output.
#pragma once

namespace scatterlab {

// Starts the handling. Call once, at the start of main, before any other thread exists: it
// blocks the signals in the calling thread, and every thread started afterwards inherits that,
// so only the handling thread ever receives them. Calling it again does nothing.
void installInterruptCleanup();

}  // namespace scatterlab
