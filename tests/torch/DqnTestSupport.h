// Shared by the DQN trainer and graph-state tests: sample plans, a small training set-up
// and a model serialised to memory.
#pragma once

#include "SmallNetwork.h"
#include "formats/PlanIO.h"
#include "learning/dqn/DqnModelFile.h"
#include "learning/dqn/DqnTrainer.h"
#include "pipeline/Planner.h"

#include <sstream>
#include <string>

namespace fc::test {

inline Plan samplePlan(const std::string& name) {
    return loadProjectFile(std::string(FC_PLANS_DIR) + "/" + name + ".geojson").plan;
}

inline PreparedPlan preparedSample(const std::string& name) {
    return preparePlan(samplePlan(name), RobotProfile{}, 90.0);
}

// A small network and schedule, so that a test trains in a second or two.
inline TrainingOptions smallOptions(TrainingOptions options) {
    shrinkForTests(options.agent);
    options.agent.replayCapacity = 2000;
    options.agent.epsilonDecaySteps = 300;
    return options;
}

inline std::string serialized(const DqnTrainer& trainer) {
    std::ostringstream out;
    writeDqnModel(out, trainer.modelInfo(), trainer.agent());
    return out.str();
}

} // namespace fc::test
