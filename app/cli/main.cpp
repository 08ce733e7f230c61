// floorcover-cli: thin command-line front end over the planner core (SPEC sect. 7).
#include "CliCommands.h"

int main(int argc, char** argv) {
    return fc::cli::run(argc, argv);
}
