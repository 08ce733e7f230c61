// Shared by the CLI commands: the plan options and how they become a PlanRequest.
#pragma once

#include "Arguments.h"
#include "formats/PlanIO.h"
#include "pipeline/Planner.h"

#include <string>
#include <vector>

namespace fc::cli {

extern const std::vector<std::string> kPlanOptions;

// A request from the project file's settings, overridden by command-line options.
PlanRequest requestFrom(const Project& project, const Arguments& args);
// The one positional PLAN argument; throws InputError otherwise.
const std::string& planPath(const Arguments& args);

int commandTrain(const Arguments& args);
int commandTile(const Arguments& args);   // TileCommand.cpp: the tiling robot
int commandImport(const Arguments& args); // ImportCommand.cpp: DXF, ROS maps, WKT to a plan

} // namespace fc::cli
