#pragma once
// Text from a file or the command line, made fit for a one-line error message on a terminal
// (DESIGN.md: one clear line naming the input and what is wrong). A hostile or corrupt input can
// hold anything: control bytes that move the cursor or end the line, bytes that are not UTF-8
// (a UTF-16 file), NUL bytes that would cut a C string, a token of ten megabytes. Everything that
// quotes input in a message goes through here.
#include <cstddef>
#include <string>
#include <string_view>

namespace strata {

// `text` with control bytes written as \n, \r, \t, \0 or \xNN, a backslash as \\, and every
// byte that does not belong to a well-formed UTF-8 sequence as \xNN; valid multi-byte UTF-8 is
// kept. When the result would be longer than `maxChars` characters (an escape counts as its
// length, a UTF-8 character as one), it is cut at a character boundary and "..." appended, so
// the result never exceeds maxChars + 3.
std::string printable(std::string_view text, std::size_t maxChars = 60);

// A whole message, escaped the same way; when longer than `maxChars` its head and its tail are
// kept around "..." (a message names its input first and its cause last, so both survive).
std::string printableMessage(std::string_view text, std::size_t maxChars = 300);

}  // namespace strata
