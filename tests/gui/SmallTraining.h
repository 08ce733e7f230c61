// A DQN small enough to train for a few seconds in a GUI test.
#pragma once

#include "learning/dqn/DqnTrainer.h"

namespace fc::ui::test {

inline TrainingOptions smallTrainingOptions() {
    TrainingOptions o = TrainingOptions::improved(1);
    o.agent.conv1Channels = o.agent.conv2Channels = o.agent.conv3Channels = 8;
    o.agent.hiddenUnits = 32;
    o.agent.learningStarts = 50;
    o.agent.batchSize = 16;
    return o;
}

} // namespace fc::ui::test
