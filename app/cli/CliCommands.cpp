#include "CliCommands.h"

#include <iostream>

namespace fc::cli {
int run(int, char**) {
    std::cerr << "floorcover-cli: commands are being assembled in this build\n";
    return 1;
}
} // namespace fc::cli
