// floorcover-cli: thin command-line front end over the planner core (SPEC sect. 7).
#include "CliCommands.h"
#include "learning/dqn/DqnSolver.h"
#include "tiling/ppo/PpoOrdering.h"

int main(int argc, char** argv) {
    fc::registerDqnSolver();
    fc::registerPpoOrdering();
    return fc::cli::run(argc, argv);
}
