#pragma once
// GL error policy: KHR_debug messages of high severity (and glGetError results) are recorded
// and counted, never ignored. `checkGl(where)` turns anything recorded since the last check into
// a std::runtime_error; tests call it after every GL step, the command line after each frame.
#include <cstddef>
#include <string>
#include <vector>

namespace strata::gl {

// Installs the KHR_debug callback on the current context (synchronous output).
void installDebugCallback();

// Messages of error severity recorded since the last take; clears them.
std::vector<std::string> takeErrors();

// How many GL errors this process has seen in total (for the stats panel and reports).
std::size_t errorCount();

// Throws std::runtime_error("GL error at <where>: <first message>") when errors are pending.
void checkGl(const char* where);

// Whether the environment variable `name` is "1": the STRATA_DEBUG_* switches of a GPU
// diagnostic run (docs/testing.md), read once by each caller (a static).
bool debugSwitch(const char* name);

}  // namespace strata::gl
