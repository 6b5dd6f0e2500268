#pragma once
// Runs another program to completion (gnuplot for the report's chart): found on PATH, its
// standard input fed from a string, its standard output and error captured together. No shell
// is involved, so arguments reach the program exactly as given.
#include <string>
#include <string_view>
#include <vector>

namespace strata {

struct ProgramResult {
    int exitCode = -1;   // the program's exit status; 128 + N when signal N ended it
    std::string output;  // standard output and standard error, interleaved as written
};

// Throws std::runtime_error "<program>: <why>" when it cannot be started (not on PATH, no
// resources). `arguments[0]` is the program's name.
ProgramResult runProgram(const std::vector<std::string>& arguments, std::string_view input = {});

// Whether `name` is an executable file in a PATH folder.
bool programOnPath(const std::string& name);

}  // namespace strata
