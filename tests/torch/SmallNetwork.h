// A small network and schedule for the DQN tests, so that a test trains in a second or two.
#pragma once

#include "learning/torch/DqnAgent.h"

namespace fc::test {

inline void shrinkForTests(DqnHyperParameters& p) {
    p.conv1Channels = p.conv2Channels = p.conv3Channels = 8;
    p.hiddenUnits = 32;
    p.batchSize = 16;
    p.learningStarts = 50;
    p.targetSyncInterval = 100;
}

} // namespace fc::test
