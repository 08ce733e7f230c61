// Whole-file reading and atomic writing, for every reader and writer of the planner.
#pragma once

#include <string>

namespace fc {

// Atomic write (temporary file + rename). Throws InputError on failure.
void writeFileAtomically(const std::string& path, const std::string& contents);
std::string readFile(const std::string& path); // throws InputError
// A text without the UTF-8 byte order mark some Windows editors write at its start.
std::string withoutByteOrderMark(std::string text);

} // namespace fc
