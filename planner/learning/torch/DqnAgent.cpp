#include "learning/torch/DqnAgent.h"

#include "learning/torch/DqnNetwork.h"
#include "learning/torch/DqnTargets.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <dlfcn.h>
#include <iterator>
#include <limits>
#include <malloc.h>
#include <mutex>
#include <stdexcept>
#include <string>

namespace fc {

namespace {

// One intra-op thread: reproducible results, and Debian's generic BLAS gains nothing from
// more. The OpenMP setting is per calling thread, so every entry point checks it (training
// runs on worker threads).
void useOneThread() {
    if (at::get_num_threads() != 1)
        at::set_num_threads(1);
    // Debian's libtorch calls the generic BLAS; when that is OpenBLAS its own thread pool
    // would oversubscribe the cores (as OPENBLAS_NUM_THREADS=1 avoids). Looked up at run
    // time because the reference BLAS has no such function.
    static std::once_flag blasOnce;
    std::call_once(blasOnce, [] {
        // LibTorch allocates its batch tensors (hundreds of kB) with malloc; above glibc's
        // mmap threshold every one is a fresh mapping whose pages fault in zeroed, and on a
        // virtual machine that cost three times the arithmetic (measured on office's graph
        // state). Keep such blocks in the heap and do not trim it after every step.
        mallopt(M_MMAP_THRESHOLD, 64 << 20);
        mallopt(M_TRIM_THRESHOLD, 256 << 20);
        if (std::getenv("FC_NO_MKLDNN"))
            at::globalContext().setUserEnabledMkldnn(false);
        using SetThreads = void (*)(int);
        if (auto set =
                reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads")))
            set(1);
    });
}

int uniformChoice(const std::vector<char>& mask, int count, bool masked, std::mt19937_64& rng) {
    std::vector<int> choices;
    if (masked)
        for (int a = 0; a < count; ++a)
            if (mask[static_cast<std::size_t>(a)])
                choices.push_back(a);
    if (choices.empty()) {
        std::uniform_int_distribution<int> pick(0, count - 1);
        return pick(rng);
    }
    std::uniform_int_distribution<std::size_t> pick(0, choices.size() - 1);
    return choices[pick(rng)];
}

} // namespace

struct DqnAgent::Impl {
    QNetwork online;
    QNetwork target;
    torch::optim::Adam optimizer;

    Impl(int imageSize, int actionCount, const DqnHyperParameters& params)
        : online(imageSize, actionCount, params), target(imageSize, actionCount, params),
          optimizer(online->parameters(), torch::optim::AdamOptions(params.learningRate)) {
        target->eval();
        for (auto& p : target->parameters())
            p.set_requires_grad(false);
        copyWeights(online, target);
    }
};

DqnAgent::DqnAgent(int imageSize, int actionCount, DqnHyperParameters params)
    : imageSize_(imageSize), actionCount_(actionCount), params_(params),
      memory_(static_cast<std::size_t>(params.replayCapacity > 0 ? params.replayCapacity : 1)),
      demonstrations_(static_cast<std::size_t>(std::max(1, params.demonstrationCapacity))),
      rng_(params.seed) {
    if (params.replayCapacity <= 0 || params.batchSize <= 0 || params.targetSyncInterval <= 0 ||
        params.trainInterval <= 0 || params.inputChannels <= 0)
        throw std::invalid_argument("DqnAgent: capacity, batch and intervals must be positive");
    useOneThread();
    torch::manual_seed(params.seed);
    impl_ = std::make_unique<Impl>(imageSize, actionCount, params_);
}

DqnAgent::~DqnAgent() = default;

std::size_t DqnAgent::observationSize() const {
    const auto channels = static_cast<std::size_t>(params_.inputChannels);
    return params_.network == QNetworkKind::Graph
               ? channels * static_cast<std::size_t>(actionCount_)
               : channels * static_cast<std::size_t>(imageSize_) *
                     static_cast<std::size_t>(imageSize_);
}
DqnAgent::DqnAgent(DqnAgent&&) noexcept = default;
DqnAgent& DqnAgent::operator=(DqnAgent&&) noexcept = default;

std::vector<float> DqnAgent::qValues(const std::vector<float>& observations, int batch) const {
    return evaluate(false, observations, batch);
}

std::vector<float> DqnAgent::targetQValues(const std::vector<float>& observations,
                                           int batch) const {
    useOneThread();
    return evaluate(true, observations, batch);
}

std::vector<float> DqnAgent::evaluate(bool target, const std::vector<float>& observations,
                                      int batch) const {
    // The graph network takes any corner count (sizeFree); the image network its own size.
    const std::size_t perSample =
        batch > 0 ? observations.size() / static_cast<std::size_t>(batch) : 0;
    const bool fits =
        sizeFree()
            ? perSample > 0 && perSample % static_cast<std::size_t>(params_.inputChannels) == 0
            : perSample == observationSize();
    if (batch <= 0 || !fits || perSample * static_cast<std::size_t>(batch) != observations.size())
        throw std::invalid_argument("DqnAgent::qValues: observation size mismatch");
    const auto length = static_cast<std::int64_t>(perSample);
    torch::NoGradGuard noGrad;
    const torch::Tensor input =
        torch::from_blob(const_cast<float*>(observations.data()), {batch, length}, torch::kFloat32);
    QNetwork& network = target ? impl_->target : impl_->online;
    const torch::Tensor q = network->forward(input).contiguous();
    return std::vector<float>(q.data_ptr<float>(), q.data_ptr<float>() + q.numel());
}

int DqnAgent::greedyAction(const std::vector<float>& observation,
                           const std::vector<char>& mask) const {
    const std::vector<float> q = qValues(observation, 1);
    const int actions = static_cast<int>(q.size());
    int best = -1;
    if (params_.maskActions && static_cast<int>(mask.size()) == actions)
        best = maskedArgmax(q.data(), mask.data(), actions);
    if (best < 0)
        best = maskedArgmax(q.data(), nullptr, actions);
    return best;
}

int DqnAgent::act(const std::vector<float>& observation, const std::vector<char>& mask,
                  double epsilon, std::mt19937_64& rng) const {
    const int actions = actionsIn(observation);
    if (params_.maskActions && static_cast<int>(mask.size()) != actions)
        throw std::invalid_argument("DqnAgent::act: mask size differs from the action count");
    std::uniform_real_distribution<double> coin(0.0, 1.0);
    if (coin(rng) < epsilon)
        return uniformChoice(mask, actions, params_.maskActions, rng);
    return greedyAction(observation, mask);
}

int DqnAgent::actionsIn(const std::vector<float>& observation) const {
    if (!sizeFree())
        return actionCount_;
    return static_cast<int>(observation.size() / static_cast<std::size_t>(params_.inputChannels));
}

void DqnAgent::remember(Transition transition) {
    if (!fits(transition))
        throw std::invalid_argument("DqnAgent::remember: transition does not fit the agent");
    memory_.push(std::move(transition));
}

void DqnAgent::rememberDemonstration(Transition transition) {
    if (!sizeFree() || !fits(transition))
        throw std::invalid_argument("DqnAgent::rememberDemonstration: needs the graph network and "
                                    "a transition that fits it");
    demonstrations_.push(std::move(transition));
}

bool DqnAgent::fits(const Transition& transition) const {
    const auto channels = static_cast<std::size_t>(params_.inputChannels);
    const bool sized =
        sizeFree()
            ? !transition.observation.empty() && transition.observation.size() % channels == 0 &&
                  transition.nextObservation.size() == transition.nextMask.size() * channels &&
                  transition.action < actionsIn(transition.observation)
            : transition.observation.size() == observationSize() &&
                  transition.nextObservation.size() == observationSize() &&
                  transition.nextMask.size() == static_cast<std::size_t>(actionCount_) &&
                  transition.action < actionCount_;
    return sized && transition.action >= 0;
}

namespace {

// Observations of one batch laid out back to back, each padded to `corners` corners with
// zero rows (invalid corners, which the graph network ignores); masks padded with 0.
void appendPadded(const std::vector<float>& from, std::size_t length, std::vector<float>& to) {
    const std::size_t at = to.size();
    to.resize(at + length, 0.0f);
    std::copy(from.begin(), from.end(), to.begin() + static_cast<std::ptrdiff_t>(at));
}

} // namespace

double DqnAgent::trainStep(bool demonstrationsOnly) {
    useOneThread();
    const auto batch = static_cast<std::size_t>(params_.batchSize);
    // Rows from the agent's own memory first, then from the demonstrations. Without
    // demonstrations the draws are those of plain Double DQN.
    std::size_t fromDemonstrations = 0;
    if (demonstrations_.size() > 0)
        fromDemonstrations =
            demonstrationsOnly || memory_.size() == 0
                ? batch
                : std::min(batch, static_cast<std::size_t>(std::lround(
                                      params_.demonstrationShare * static_cast<double>(batch))));
    else if (demonstrationsOnly)
        throw std::logic_error("DqnAgent::trainStep: no demonstrations");
    const std::size_t fromMemory = batch - fromDemonstrations;
    std::vector<const Transition*> items;
    items.reserve(batch);
    if (fromMemory > 0)
        for (std::size_t index : memory_.sample(fromMemory, rng_))
            items.push_back(&memory_.at(index));
    if (fromDemonstrations > 0)
        for (std::size_t index : demonstrations_.sample(fromDemonstrations, rng_))
            items.push_back(&demonstrations_.at(index));
    const auto channels = static_cast<std::size_t>(params_.inputChannels);
    // Graph network: transitions of graphs of different sizes share a batch, padded to the
    // largest (separately for the states and the next states).
    std::size_t pixels = observationSize();
    std::size_t nextPixels = pixels;
    if (sizeFree()) {
        pixels = nextPixels = 0;
        for (const Transition* t : items) {
            pixels = std::max(pixels, t->observation.size());
            nextPixels = std::max(nextPixels, t->nextObservation.size());
        }
        nextPixels = std::max(nextPixels, channels); // a terminal state may have no corner
    }
    const std::size_t actions =
        sizeFree() ? nextPixels / channels : static_cast<std::size_t>(actionCount_);

    std::vector<float> observations;
    std::vector<float> nextObservations;
    observations.reserve(batch * pixels);
    nextObservations.reserve(batch * nextPixels);
    std::vector<std::int64_t> chosen(batch);
    DoubleDqnBatch targetsInput;
    targetsInput.actionCount = static_cast<int>(actions);
    targetsInput.rewards.resize(batch);
    targetsInput.dones.resize(batch);
    targetsInput.steps.resize(batch);
    targetsInput.nextMask.assign(batch * actions, 0);
    for (std::size_t i = 0; i < batch; ++i) {
        const Transition& t = *items[i];
        appendPadded(t.observation, pixels, observations);
        appendPadded(t.nextObservation, nextPixels, nextObservations);
        std::copy(t.nextMask.begin(), t.nextMask.end(),
                  targetsInput.nextMask.begin() + static_cast<std::ptrdiff_t>(i * actions));
        chosen[i] = t.action;
        targetsInput.rewards[i] = t.reward;
        targetsInput.dones[i] = t.done ? 1.0f : 0.0f;
        targetsInput.steps[i] = t.steps;
    }

    const auto b = static_cast<std::int64_t>(batch);
    const auto length = static_cast<std::int64_t>(pixels);
    const torch::Tensor next = torch::from_blob(
        nextObservations.data(), {b, static_cast<std::int64_t>(nextPixels)}, torch::kFloat32);
    {
        torch::NoGradGuard noGrad;
        const torch::Tensor onlineQ = impl_->online->forward(next).contiguous();
        const torch::Tensor targetQ = impl_->target->forward(next).contiguous();
        targetsInput.nextOnlineQ.assign(onlineQ.data_ptr<float>(),
                                        onlineQ.data_ptr<float>() + onlineQ.numel());
        targetsInput.nextTargetQ.assign(targetQ.data_ptr<float>(),
                                        targetQ.data_ptr<float>() + targetQ.numel());
    }
    std::vector<float> y =
        doubleDqnTargets(targetsInput, static_cast<float>(params_.gamma), params_.maskTargetArgmax);

    const torch::Tensor input = torch::from_blob(observations.data(), {b, length}, torch::kFloat32);
    const torch::Tensor actionIndex = torch::from_blob(chosen.data(), {b, 1}, torch::kInt64);
    const torch::Tensor targets = torch::from_blob(y.data(), {b}, torch::kFloat32);

    impl_->online->train();
    const torch::Tensor allQ = impl_->online->forward(input);
    const torch::Tensor q = allQ.gather(1, actionIndex).squeeze(1);
    torch::Tensor loss = torch::huber_loss(q, targets, at::Reduction::Mean, params_.huberDelta);
    std::vector<float> margins;
    if (fromDemonstrations > 0 && params_.marginWeight > 0.0) {
        // Expert rows: + margin on every other valid corner, a large negative on invalid ones.
        const std::size_t corners = pixels / channels;
        margins.assign(fromDemonstrations * corners, -1e9f);
        for (std::size_t r = 0; r < fromDemonstrations; ++r) {
            const Transition& t = *items[fromMemory + r];
            for (std::size_t c = 0; c * channels < t.observation.size(); ++c)
                if (t.observation[c * channels] > 0.5f)
                    margins[r * corners + c] = static_cast<float>(params_.margin);
            margins[r * corners + static_cast<std::size_t>(t.action)] = 0.0f;
        }
        const auto rows = static_cast<std::int64_t>(fromDemonstrations);
        const torch::Tensor offsets = torch::from_blob(
            margins.data(), {rows, static_cast<std::int64_t>(corners)}, torch::kFloat32);
        const auto first = static_cast<std::int64_t>(fromMemory);
        const torch::Tensor best = std::get<0>((allQ.narrow(0, first, rows) + offsets).max(1));
        const torch::Tensor hinge = (best - q.narrow(0, first, rows)).mean();
        lastMarginLoss_ = hinge.item<double>();
        loss = loss + params_.marginWeight * hinge;
    }
    impl_->optimizer.zero_grad();
    loss.backward();
    if (params_.gradientClipNorm > 0.0)
        torch::nn::utils::clip_grad_norm_(impl_->online->parameters(), params_.gradientClipNorm);
    impl_->optimizer.step();
    ++trainSteps_;
    return loss.item<double>();
}

void DqnAgent::syncTarget() {
    copyWeights(impl_->online, impl_->target);
}

double DqnAgent::epsilon() const {
    if (params_.epsilonDecaySteps <= 0 || steps_ >= params_.epsilonDecaySteps)
        return params_.epsilonEnd;
    const double fraction =
        static_cast<double>(steps_) / static_cast<double>(params_.epsilonDecaySteps);
    return params_.epsilonStart + fraction * (params_.epsilonEnd - params_.epsilonStart);
}

double DqnAgent::observe(Transition transition) {
    remember(std::move(transition));
    ++steps_;
    double loss = std::numeric_limits<double>::quiet_NaN();
    if (steps_ >= params_.learningStarts && steps_ % params_.trainInterval == 0)
        loss = trainStep();
    if (steps_ % params_.targetSyncInterval == 0)
        syncTarget();
    return loss;
}

void DqnAgent::saveWeights(std::ostream& out) const {
    torch::serialize::OutputArchive archive;
    impl_->online->save(archive);
    archive.save_to(out);
}

void DqnAgent::loadWeights(std::istream& in) {
    // InputArchive replaces tensors of any shape: load into a scratch network, check the shapes,
    // then copy, so that a model of another architecture leaves this agent untouched.
    QNetwork loaded(imageSize_, actionCount_, params_);
    try {
        torch::serialize::InputArchive archive;
        archive.load_from(in);
        loaded->load(archive);
    } catch (const c10::Error& e) {
        throw std::runtime_error(std::string("DqnAgent: cannot load weights (another "
                                             "architecture or a corrupt archive): ") +
                                 e.what_without_backtrace());
    }
    const auto expected = impl_->online->named_parameters(true);
    const auto actual = loaded->named_parameters(true);
    if (expected.size() != actual.size())
        throw std::runtime_error("DqnAgent: weights of another architecture");
    for (const auto& item : expected) {
        const torch::Tensor* other = actual.find(item.key());
        if (other == nullptr || other->sizes() != item.value().sizes())
            throw std::runtime_error("DqnAgent: weights of another architecture");
    }
    copyWeights(loaded, impl_->online);
    syncTarget();
}

void DqnAgent::saveOptimizer(std::ostream& out) const {
    torch::serialize::OutputArchive archive;
    impl_->optimizer.save(archive);
    archive.save_to(out);
}

void DqnAgent::loadOptimizer(std::istream& in) {
    // Load into a scratch optimiser over a scratch network first, so that a bad stream leaves
    // this agent's optimiser untouched.
    QNetwork scratch(imageSize_, actionCount_, params_);
    torch::optim::Adam check(scratch->parameters(),
                             torch::optim::AdamOptions(params_.learningRate));
    std::string bytes(std::istreambuf_iterator<char>(in), {});
    try {
        torch::serialize::InputArchive archive;
        archive.load_from(bytes.data(), bytes.size());
        check.load(archive);
        torch::serialize::InputArchive again;
        again.load_from(bytes.data(), bytes.size());
        impl_->optimizer.load(again);
    } catch (const c10::Error& e) {
        throw std::runtime_error(std::string("DqnAgent: cannot load the optimiser state: ") +
                                 e.what_without_backtrace());
    }
}

void DqnAgent::restoreCounters(long steps, long trainSteps) {
    if (steps < 0 || trainSteps < 0)
        throw std::invalid_argument("DqnAgent::restoreCounters: negative count");
    steps_ = steps;
    trainSteps_ = trainSteps;
}

} // namespace fc
