// Small helpers shared by the bench tools (header only).
#pragma once

#include <ctime>
#include <sstream>
#include <string>
#include <vector>

namespace fc::bench {

// "a,b,,c" -> {"a", "b", "c"}
inline std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');)
        if (!item.empty())
            out.push_back(item);
    return out;
}

// CPU time of the calling thread: budgets and curves that other work on a shared machine does
// not change (one thread = one dedicated core).
inline double threadCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

} // namespace fc::bench
