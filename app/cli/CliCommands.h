#pragma once

namespace fc::cli {
// Parses the command line and runs plan|graph|compare. Returns the process exit code:
// 0 success, 2 bad input (one line on stderr naming the file and the problem), 1 other.
int run(int argc, char** argv);
} // namespace fc::cli
