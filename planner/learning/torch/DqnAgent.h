// Double-DQN agent (SPEC sect. 5; van Hasselt et al. 2016) over the CoverageEnvironment's
// channels x SIZE x SIZE observations, one action per corner-graph node. LibTorch stays behind a
// pimpl: this header exposes no torch types.
//
// Faithful defaults (the paper's network and optimiser): 3 convolution + 2 dense layers, Adam
// with lr 2.5e-4, gamma 0.99, batch 32, replay 50,000, epsilon 1.0 -> 0.05 linearly, target
// sync every 1,000 steps, learning after 500 steps. Improvements are switches: action masking
// when acting and in the Double-DQN argmax (on by default), gradient-norm clipping (off).
#pragma once

#include "learning/torch/ReplayMemory.h"

#include <cstdint>
#include <iosfwd>
#include <memory>
#include <random>
#include <vector>

namespace fc {

// Convolutional: the paper's image network. Graph: a per-corner network over the
// environment's graph-level state (actionCount x inputChannels features, node-major): a shared
// encoder (inputChannels -> hidden -> hidden) of the valid corners (feature 0 marks them), a
// context of the mean and max of their encodings (2 x hidden -> hidden), and a shared head
// (encoding + context -> hidden -> 1) giving Q(s, a) per valid corner; other corners get 0.
enum class QNetworkKind { Convolutional, Graph };

struct DqnHyperParameters {
    QNetworkKind network = QNetworkKind::Convolutional;
    // Network: conv inputChannels -> conv1 -> conv2 -> conv3 (3x3, padding 1, ReLU), dense ->
    // hidden -> actions. The graph network uses inputChannels and hiddenUnits only.
    int inputChannels = 3; // the paper's image; 5 with the environment's cost channels; the
                           // graph state's features per corner
    int conv1Channels = 32;
    int conv2Channels = 64;
    int conv3Channels = 64;
    int hiddenUnits = 256;
    // Graph network only: rounds of messages between neighbouring valid corners after the
    // encoder (0: none, the first graph network). In each round a corner takes the max over
    // its messageNeighbours nearest valid corners (itself included) of a message computed
    // from their encoding and their offset (scaled by the state's mean neighbour distance),
    // and adds it to its encoding (residual), so that a corner's score sees the uncovered
    // cells around it, not only a floor-wide mean and max.
    int messageRounds = 0;
    int messageNeighbours = 12;
    // Learning.
    double learningRate = 2.5e-4;
    double gamma = 0.99;
    int batchSize = 32;
    int replayCapacity = 50'000;
    double huberDelta = 1.0;
    double gradientClipNorm = 0.0; // <= 0: no clipping
    // Exploration: linear from epsilonStart to epsilonEnd over epsilonDecaySteps steps.
    double epsilonStart = 1.0;
    double epsilonEnd = 0.05;
    long epsilonDecaySteps = 100'000;
    // Schedule (in environment steps).
    int targetSyncInterval = 1'000;
    int learningStarts = 500;
    int trainInterval = 1; // one gradient step every trainInterval environment steps
    std::uint64_t seed = 1;
    // Improvements over the paper.
    bool maskActions = true;      // act only among valid actions
    bool maskTargetArgmax = true; // Double-DQN argmax only among valid next actions
    // Learning from demonstrations (DQfD, Hester et al. 2018; graph network only). Once expert
    // transitions are given (rememberDemonstration), demonstrationShare of every batch is drawn
    // from them, and those rows add the large-margin loss
    //   marginWeight x (max over valid a of [Q(s, a) + margin x (a != a_E)] - Q(s, a_E)),
    // which ranks the expert's corner first; the TD loss still fits the values.
    double demonstrationShare = 0.25;
    double margin = 0.2; // in reward units (longest edges in the graph setting)
    double marginWeight = 1.0;
    int demonstrationCapacity = 20'000;
};

class DqnAgent {
public:
    // Seeds torch (global generator) and the agent's own generator from params.seed. Every
    // torch call runs with one intra-op thread (at::set_num_threads(1) on the calling thread).
    DqnAgent(int imageSize, int actionCount, DqnHyperParameters params = {});
    ~DqnAgent();
    DqnAgent(DqnAgent&&) noexcept;
    DqnAgent& operator=(DqnAgent&&) noexcept;
    DqnAgent(const DqnAgent&) = delete;
    DqnAgent& operator=(const DqnAgent&) = delete;

    // Epsilon-greedy: with probability epsilon a uniformly random action (a valid one when
    // masking), otherwise the (masked) argmax of the online network. The mask has one entry
    // per action; when masking and no action is valid, the unmasked choice is made.
    int act(const std::vector<float>& observation, const std::vector<char>& mask, double epsilon,
            std::mt19937_64& rng) const;
    // Greedy action (epsilon 0).
    int greedyAction(const std::vector<float>& observation, const std::vector<char>& mask) const;

    // Online Q values for `batch` observations laid out back to back: batch x actionCount
    // (graph network: batch x the observations' corner count, the same for all of them).
    std::vector<float> qValues(const std::vector<float>& observations, int batch) const;
    // The same from the target network.
    std::vector<float> targetQValues(const std::vector<float>& observations, int batch) const;

    void remember(Transition transition);
    // An expert transition (graph network only; std::invalid_argument otherwise or when it does
    // not fit). Kept apart from the replay memory, never overwritten by the agent's own steps.
    void rememberDemonstration(Transition transition);
    std::size_t demonstrationCount() const { return demonstrations_.size(); }
    const ReplayMemory& demonstrations() const { return demonstrations_; }
    // The margin loss of the last step's expert rows (before its weight); 0 when none.
    double lastMarginLoss() const { return lastMarginLoss_; }
    // One Double-DQN gradient step on a batch sampled from the replay memory (and the
    // demonstrations, with their margin loss); returns the loss. demonstrationsOnly: the whole
    // batch from the demonstrations (pre-training). Throws std::logic_error when what it
    // samples from is empty.
    double trainStep(bool demonstrationsOnly = false);
    // Copies the online network's parameters and buffers into the target network.
    void syncTarget();

    // The whole schedule for one environment step: remember the transition, count the step,
    // train when due (after learningStarts, every trainInterval steps, returning the loss),
    // sync the target every targetSyncInterval steps. Returns NaN when no training happened.
    double observe(Transition transition);
    double epsilon() const; // at the current step count
    long stepCount() const { return steps_; }
    long trainStepCount() const { return trainSteps_; }

    // Online network weights (torch::save format) to/from a stream; loading also syncs the
    // target. Throws std::runtime_error on a stream that does not fit this architecture.
    void saveWeights(std::ostream& out) const;
    void loadWeights(std::istream& in);
    // Adam's moments, so that a resumed training continues where it stopped. Throws
    // std::runtime_error on a stream that does not fit.
    void saveOptimizer(std::ostream& out) const;
    void loadOptimizer(std::istream& in);
    // Step counters of a resumed training (epsilon schedule, target sync phase).
    void restoreCounters(long steps, long trainSteps);

    int imageSize() const { return imageSize_; }
    // Floats per observation: inputChannels x SIZE x SIZE, or actionCount x inputChannels.
    std::size_t observationSize() const;
    int actionCount() const { return actionCount_; }
    // The graph network scores graphs of any corner count: its observations, masks and
    // transitions may have any number of corners (actionCount is then the size it was made
    // for, nothing more), and one model serves every floor plan (a generalist).
    bool sizeFree() const { return params_.network == QNetworkKind::Graph; }
    // Actions of one observation: its corners for the graph network, else actionCount.
    int actionsIn(const std::vector<float>& observation) const;
    const DqnHyperParameters& parameters() const { return params_; }
    const ReplayMemory& memory() const { return memory_; }

private:
    struct Impl;
    bool fits(const Transition& transition) const;
    std::vector<float> evaluate(bool target, const std::vector<float>& observations,
                                int batch) const;
    std::unique_ptr<Impl> impl_;
    int imageSize_ = 0;
    int actionCount_ = 0;
    DqnHyperParameters params_;
    ReplayMemory memory_;
    ReplayMemory demonstrations_;
    std::mt19937_64 rng_; // replay sampling
    long steps_ = 0;
    long trainSteps_ = 0;
    double lastMarginLoss_ = 0.0;
};

} // namespace fc
