#include "tiling/ppo/torch/PointerPpo.h"

#include "model/Plan.h"
#include "tiling/ppo/TourBuilder.h"
#include "tiling/ppo/TrainingInstances.h"
#include "tiling/ppo/torch/LocalPointer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <dlfcn.h>
#include <mutex>

namespace fc {
namespace {

using tiling::kCandidateFeatures;
using tiling::TourBuilder;

// One intra-op thread (reproducible, and the generic BLAS gains nothing from more); the
// OpenMP setting is per calling thread. OpenBLAS's own pool is set once, when present.
void singleThreaded() {
    if (at::get_num_threads() != 1)
        at::set_num_threads(1);
    static std::once_flag once;
    std::call_once(once, [] {
        using SetThreads = void (*)(int);
        if (auto set =
                reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads")))
            set(1);
    });
}

torch::Tensor clippedLoss(const torch::Tensor& logp, const torch::Tensor& oldLogp,
                          const torch::Tensor& advantage, double clip) {
    const torch::Tensor ratio = torch::exp(logp - oldLogp);
    const torch::Tensor clipped = torch::clamp(ratio, 1.0 - clip, 1.0 + clip);
    return -torch::min(ratio * advantage, clipped * advantage).mean();
}

// Tours built in lockstep (all builders have problems of one size); what the update needs
// is recorded per step.
struct Rollout {
    std::vector<torch::Tensor> candidates, lastMoves, masks, actions, logps, values;
    std::vector<std::vector<double>> energies; // [step][builder]
};

Rollout roll(LocalPointer& net, std::vector<TourBuilder>& builders, int window, int greedyCount) {
    torch::NoGradGuard noGrad;
    Rollout r;
    const auto batch = static_cast<int64_t>(builders.size());
    const int64_t row = static_cast<int64_t>(window) * kCandidateFeatures;
    auto state =
        std::make_tuple(torch::zeros({batch, net->hidden}), torch::zeros({batch, net->hidden}));
    const auto running = [&builders] {
        return std::any_of(builders.begin(), builders.end(),
                           [](const TourBuilder& b) { return !b.done(); });
    };
    while (running()) {
        torch::Tensor x = torch::empty({batch, window, kCandidateFeatures});
        torch::Tensor last = torch::empty({batch, kCandidateFeatures});
        torch::Tensor mask = torch::zeros({batch, window}, torch::kBool);
        for (int64_t b = 0; b < batch; ++b) {
            const TourBuilder& builder = builders[static_cast<std::size_t>(b)];
            std::copy_n(builder.features().data(), row, x.data_ptr<float>() + b * row);
            std::copy_n(builder.lastMove().data(), kCandidateFeatures,
                        last.data_ptr<float>() + b * kCandidateFeatures);
            mask[b].narrow(0, 0, static_cast<int64_t>(builder.candidates().size())).fill_(true);
        }
        state = net->decode(last, state);
        const auto [encoded, keys] = net->encode(x);
        const torch::Tensor logp = net->logProbabilities(keys, std::get<0>(state), mask);
        torch::Tensor action = torch::multinomial(logp.exp(), 1).squeeze(1);
        if (greedyCount > 0)
            action.narrow(0, 0, greedyCount).copy_(logp.narrow(0, 0, greedyCount).argmax(1));
        r.values.push_back(net->value(encoded, std::get<0>(state), mask));
        r.logps.push_back(logp.gather(1, action.unsqueeze(1)).squeeze(1));
        r.candidates.push_back(x);
        r.lastMoves.push_back(last);
        r.masks.push_back(mask);
        r.actions.push_back(action);
        std::vector<double> energy;
        auto chosen = action.accessor<int64_t, 1>();
        for (int64_t b = 0; b < batch; ++b) { // a builder done early (a smaller problem) waits
            TourBuilder& builder = builders[static_cast<std::size_t>(b)];
            energy.push_back(builder.done() ? 0.0 : builder.step(static_cast<int>(chosen[b])));
        }
        r.energies.push_back(energy);
    }
    return r;
}

} // namespace

struct PointerPpo::Impl {
    PointerPpoOptions options;
    LocalPointer net{nullptr};
    std::unique_ptr<torch::optim::Adam> optimiser;
    std::unique_ptr<tiling::TrainingInstances> instances;
    std::uint64_t updatesDone = 0;

    explicit Impl(const PointerPpoOptions& o) : options(o) { build(); }

    void build() {
        torch::manual_seed(options.seed);
        net = LocalPointer(kCandidateFeatures, options.hidden);
        optimiser = std::make_unique<torch::optim::Adam>(
            net->parameters(), torch::optim::AdamOptions(options.learningRate));
    }

    std::vector<TourBuilder> builders(const std::vector<tiling::OrderingProblem>& problems) const {
        std::vector<TourBuilder> result;
        for (const tiling::OrderingProblem& problem : problems)
            result.emplace_back(problem, options.window, tiling::neighbourhoodOf(problem));
        return result;
    }

    // GAE advantages and returns of a rollout's scaled rewards, [T, B] each.
    std::pair<torch::Tensor, torch::Tensor> advantages(const Rollout& r, double energyUnit) const {
        const auto steps = static_cast<int64_t>(r.energies.size());
        const auto batch = static_cast<int64_t>(r.energies.front().size());
        torch::Tensor values = torch::stack(r.values);
        torch::Tensor advantage = torch::zeros({steps, batch});
        auto v = values.accessor<float, 2>();
        auto a = advantage.accessor<float, 2>();
        for (int64_t b = 0; b < batch; ++b) {
            double running = 0.0, nextValue = 0.0;
            for (int64_t t = steps - 1; t >= 0; --t) {
                const double reward = -r.energies[t][b] / energyUnit;
                const double delta = reward + options.gamma * nextValue - v[t][b];
                running = delta + options.gamma * options.lambda * running;
                a[t][b] = static_cast<float>(running);
                nextValue = v[t][b];
            }
        }
        return {advantage, advantage + values};
    }

    double update(const Rollout& r, double energyUnit) {
        const auto [advantageRaw, returns] = advantages(r, energyUnit);
        const int64_t steps = advantageRaw.size(0), batch = advantageRaw.size(1);
        torch::Tensor advantage = advantageRaw.reshape({-1});
        advantage = (advantage - advantage.mean()) / (advantage.std() + 1e-8);
        const torch::Tensor x =
            torch::stack(r.candidates).reshape({steps * batch, options.window, kCandidateFeatures});
        const torch::Tensor mask = torch::stack(r.masks).reshape({steps * batch, options.window});
        const torch::Tensor actions = torch::stack(r.actions).reshape({-1, 1});
        const torch::Tensor oldLogp = torch::stack(r.logps).reshape({-1});
        const torch::Tensor target = returns.reshape({-1});
        double criticLoss = 0.0;
        for (int epoch = 0; epoch < options.epochsPerBatch; ++epoch) {
            const auto [encoded, keys] = net->encode(x);
            auto state = std::make_tuple(torch::zeros({batch, net->hidden}),
                                         torch::zeros({batch, net->hidden}));
            std::vector<torch::Tensor> queries;
            for (int64_t t = 0; t < steps; ++t) {
                state = net->decode(r.lastMoves[t], state);
                queries.push_back(std::get<0>(state));
            }
            const torch::Tensor query = torch::stack(queries).reshape({steps * batch, -1});
            const torch::Tensor logpAll = net->logProbabilities(keys, query, mask);
            const torch::Tensor logp = logpAll.gather(1, actions).squeeze(1);
            const torch::Tensor entropy = -(logpAll.exp() * logpAll).sum(1).mean();
            const torch::Tensor valueLoss =
                torch::mse_loss(net->value(encoded, query, mask), target);
            const torch::Tensor loss = clippedLoss(logp, oldLogp, advantage, options.clip) +
                                       0.5 * valueLoss - options.entropyWeight * entropy;
            optimiser->zero_grad();
            loss.backward();
            torch::nn::utils::clip_grad_norm_(net->parameters(), 1.0);
            optimiser->step();
            criticLoss = valueLoss.item<double>();
        }
        return criticLoss;
    }
};

PointerPpo::PointerPpo(const PointerPpoOptions& options) {
    singleThreaded();
    impl_ = std::make_unique<Impl>(options);
}

PointerPpo::~PointerPpo() = default;

int PointerPpo::train(int updates, const std::function<void(const PointerPpoProgress&)>& progress,
                      double maxSeconds) {
    singleThreaded();
    Impl& m = *impl_;
    const PointerPpoOptions& o = m.options;
    const auto start = std::chrono::steady_clock::now();
    if (!m.instances)
        m.instances =
            std::make_unique<tiling::TrainingInstances>(o.seed, o.trainingRooms, o.roomWaypoints);
    int done = 0;
    for (; done < updates; ++done) {
        const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (maxSeconds > 0.0 && elapsed >= maxSeconds)
            break;
        // Torch's generator is global: reseed it per update, so that a network is
        // reproducible from its seed whatever else ran in between.
        torch::manual_seed(o.seed * 7919 + m.updatesDone);
        // Every fourth batch: scattered small instances (8 to 20 waypoints); else windows
        // of random rooms.
        const bool scattered = m.updatesDone++ % 4 == 3;
        const int size = scattered ? 8 + static_cast<int>(m.updatesDone / 4 % 13) : o.roomWaypoints;
        std::vector<tiling::OrderingProblem> problems;
        for (int k = 0; k < o.batch; ++k)
            problems.push_back(scattered ? m.instances->scattered(size)
                                         : m.instances->roomWindow(size));
        std::vector<TourBuilder> builders = m.builders(problems);
        const Rollout r = roll(m.net, builders, o.window, 0);
        if (r.energies.empty())
            continue;
        const tiling::OrderingProblem& first = problems.front();
        const double energyUnit = 4.0 * first.robot.totalMass() * first.blockLeg();
        double total = 0.0;
        for (const auto& step : r.energies)
            for (double e : step)
                total += e;
        const double criticLoss = m.update(r, energyUnit);
        if (progress)
            progress({done + 1, total / o.batch / size, criticLoss});
    }
    return done;
}

tiling::Tour PointerPpo::decodeBest(const tiling::OrderingProblem& problem, int samples,
                                    std::uint64_t seed) const {
    singleThreaded();
    if (problem.size() <= 1)
        return problem.size() == 0 ? tiling::Tour{} : tiling::Tour{0};
    torch::manual_seed(seed);
    const auto neighbourhood = tiling::neighbourhoodOf(problem);
    std::vector<TourBuilder> builders;
    for (int k = 0; k <= samples; ++k)
        builders.emplace_back(problem, impl_->options.window, neighbourhood);
    roll(impl_->net, builders, impl_->options.window, 1);
    tiling::Tour best = builders.front().tour();
    double bestCost = tiling::tourCost(problem, best);
    for (const TourBuilder& builder : builders) {
        const double cost = tiling::tourCost(problem, builder.tour());
        if (cost < bestCost) {
            bestCost = cost;
            best = builder.tour();
        }
    }
    return best;
}

tiling::Tour PointerPpo::decode(const tiling::OrderingProblem& problem) const {
    return decodeBest(problem, 0, 0);
}

std::vector<double>
PointerPpo::firstMoveProbabilities(const tiling::OrderingProblem& problem) const {
    singleThreaded();
    torch::NoGradGuard noGrad;
    const int window = impl_->options.window;
    const TourBuilder builder(problem, window, tiling::neighbourhoodOf(problem));
    const torch::Tensor x = torch::from_blob(const_cast<float*>(builder.features().data()),
                                             {1, window, kCandidateFeatures})
                                .clone();
    torch::Tensor mask = torch::zeros({1, window}, torch::kBool);
    mask[0].narrow(0, 0, static_cast<int64_t>(builder.candidates().size())).fill_(true);
    const auto state = impl_->net->decode(
        torch::zeros({1, kCandidateFeatures}),
        {torch::zeros({1, impl_->net->hidden}), torch::zeros({1, impl_->net->hidden})});
    const torch::Tensor keys = impl_->net->encode(x).second;
    const torch::Tensor p = impl_->net->logProbabilities(keys, std::get<0>(state), mask).exp()[0];
    return {p.data_ptr<float>(), p.data_ptr<float>() + window};
}

void PointerPpo::save(const std::string& path) const {
    torch::serialize::OutputArchive archive;
    impl_->net->save(archive);
    archive.write("sizes", torch::tensor({impl_->options.hidden, impl_->options.window}));
    archive.save_to(path);
}

void PointerPpo::load(const std::string& path) {
    try {
        torch::serialize::InputArchive archive;
        archive.load_from(path);
        torch::Tensor sizes;
        archive.read("sizes", sizes);
        impl_->options.hidden = static_cast<int>(sizes[0].item<int64_t>());
        impl_->options.window = static_cast<int>(sizes[1].item<int64_t>());
        impl_->build();
        impl_->net->load(archive);
    } catch (const c10::Error& e) {
        std::string why = e.what_without_backtrace();
        why = why.substr(0, std::min(why.find('\n'), std::size_t{120}));
        throw InputError(path + ": not a PPO ordering model (" + why + ")");
    }
}

double ppoClippedLoss(const std::vector<double>& newLogp, const std::vector<double>& oldLogp,
                      const std::vector<double>& advantages, double clip) {
    auto tensor = [](const std::vector<double>& v) { return torch::tensor(v, torch::kDouble); };
    return clippedLoss(tensor(newLogp), tensor(oldLogp), tensor(advantages), clip).item<double>();
}

} // namespace fc
