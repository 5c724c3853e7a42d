// A crash that says where it happened: the tools print the stack of a fatal
// signal to stderr before dying of it, so a crash seen once (a CI log, a
// user's terminal) can be traced without a core file or a rerun under gdb.
#pragma once

namespace tools {

// From now on SIGSEGV, SIGBUS, SIGFPE, SIGILL and SIGABRT print
// "TOOL: fatal signal SIGSEGV; the stack:" and the stack's frames
// (module(+offset): addr2line -e MODULE OFFSET names the line), then end the
// process by the same signal, so its exit status stays 128 + N. A signal that
// already has a handler (a sanitizer's) keeps it.
void reportCrashes(const char* tool);

} // namespace tools
