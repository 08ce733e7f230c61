#include "learning/torch/PointerPpo.h"

#include "tiling/RandomInstances.h"

#include <algorithm>
#include <cmath>
#include <torch/torch.h>

namespace fc {
namespace {

constexpr int kFeatures = 4 + tiling::kShapeCount; // x, y, cos, sin, shape one-hot

// Waypoint features scaled to the instance: positions in [0, 1], heading as cos/sin.
torch::Tensor features(const tiling::OrderingProblem& problem) {
    BoundingBox box;
    for (const tiling::Pose& pose : problem.poses)
        box.add(pose.waypoint());
    const double scale = std::max({box.width(), box.height(), 1e-9});
    torch::Tensor f = torch::zeros({problem.size(), kFeatures});
    auto a = f.accessor<float, 2>();
    for (int w = 0; w < problem.size(); ++w) {
        const tiling::Pose& pose = problem.poses[w];
        a[w][0] = static_cast<float>((pose.waypoint().x - box.minX) / scale);
        a[w][1] = static_cast<float>((pose.waypoint().y - box.minY) / scale);
        a[w][2] = static_cast<float>(std::cos(pose.heading));
        a[w][3] = static_cast<float>(std::sin(pose.heading));
        a[w][4 + static_cast<int>(pose.shape)] = 1.0f;
    }
    return f;
}

// Energy units per instance: total mass times the instance's size, so that rewards of
// floors of any size and robot are of order one per waypoint.
double costScale(const tiling::OrderingProblem& problem) {
    BoundingBox box;
    for (const tiling::Pose& pose : problem.poses)
        box.add(pose.waypoint());
    return problem.robot.totalMass() * std::max({box.width(), box.height(), 1e-9});
}

struct PointerActorImpl : torch::nn::Module {
    torch::nn::Linear embed{nullptr};
    torch::nn::LSTM encoder{nullptr};
    torch::nn::LSTMCell decoder{nullptr};
    torch::nn::Linear attendEncoded{nullptr}, attendQuery{nullptr};
    torch::Tensor attendVector;

    explicit PointerActorImpl(int hidden) {
        embed = register_module("embed", torch::nn::Linear(kFeatures, hidden));
        encoder = register_module(
            "encoder", torch::nn::LSTM(torch::nn::LSTMOptions(hidden, hidden).batch_first(true)));
        decoder = register_module("decoder", torch::nn::LSTMCell(hidden, hidden));
        attendEncoded = register_module("attend_encoded", torch::nn::Linear(hidden, hidden));
        attendQuery = register_module("attend_query", torch::nn::Linear(hidden, hidden));
        attendVector = register_parameter("attend_vector", torch::randn({hidden}) * 0.1);
    }

    // Log-probabilities of the tours: sampled (actions undefined, sample true), greedy
    // (sample false) or given (actions [B, n-1], teacher forcing). Returns (tours, logp).
    std::pair<torch::Tensor, torch::Tensor> run(torch::Tensor x, torch::Tensor actions,
                                                bool sample) {
        const auto batch = x.size(0), n = x.size(1);
        torch::Tensor embedded = embed->forward(x);
        auto [encoded, state] = encoder->forward(embedded);
        torch::Tensor keys = attendEncoded->forward(encoded); // [B, n, H]
        auto h = std::get<0>(state).squeeze(0), c = std::get<1>(state).squeeze(0);
        torch::Tensor visited = torch::zeros({batch, n}, torch::kBool);
        visited.index_put_({torch::indexing::Slice(), 0}, true);
        torch::Tensor current = torch::zeros({batch}, torch::kLong);
        const auto rows = torch::arange(batch);
        std::vector<torch::Tensor> chosen, logps;
        for (int64_t step = 1; step < n; ++step) {
            torch::Tensor input = embedded.index({rows, current});
            std::tie(h, c) = decoder->forward(input, std::make_tuple(h, c));
            torch::Tensor scores =
                torch::tanh(keys + attendQuery->forward(h).unsqueeze(1)).matmul(attendVector);
            scores = 10.0 * torch::tanh(scores); // clipped logits (Bello et al.)
            scores = scores.masked_fill(visited, -1e9);
            torch::Tensor logp = torch::log_softmax(scores, 1);
            torch::Tensor next;
            if (actions.defined())
                next = actions.index({torch::indexing::Slice(), step - 1});
            else if (sample)
                next = torch::multinomial(logp.exp(), 1).squeeze(1);
            else
                next = logp.argmax(1);
            logps.push_back(logp.gather(1, next.unsqueeze(1)).squeeze(1));
            chosen.push_back(next);
            visited = visited.scatter(1, next.unsqueeze(1), true);
            current = next;
        }
        if (chosen.empty())
            return {torch::zeros({batch, 0}, torch::kLong), torch::zeros({batch})};
        return {torch::stack(chosen, 1), torch::stack(logps, 1).sum(1)};
    }
};
TORCH_MODULE(PointerActor);

// The critic: the same encoder, a glimpse (attention-weighted sum) and two layers.
struct PointerCriticImpl : torch::nn::Module {
    torch::nn::Linear embed{nullptr};
    torch::nn::LSTM encoder{nullptr};
    torch::nn::Linear glimpse{nullptr}, hidden{nullptr}, out{nullptr};

    explicit PointerCriticImpl(int size) {
        embed = register_module("embed", torch::nn::Linear(kFeatures, size));
        encoder = register_module(
            "encoder", torch::nn::LSTM(torch::nn::LSTMOptions(size, size).batch_first(true)));
        glimpse = register_module("glimpse", torch::nn::Linear(size, 1));
        hidden = register_module("hidden", torch::nn::Linear(size, size));
        out = register_module("out", torch::nn::Linear(size, 1));
    }

    torch::Tensor forward(torch::Tensor x) {
        auto [encoded, state] = encoder->forward(embed->forward(x));
        torch::Tensor weights = torch::softmax(glimpse->forward(encoded).squeeze(2), 1);
        torch::Tensor summary = (weights.unsqueeze(2) * encoded).sum(1);
        return out->forward(torch::relu(hidden->forward(summary))).squeeze(1);
    }
};
TORCH_MODULE(PointerCritic);

} // namespace

struct PointerPpo::Impl {
    PointerPpoOptions options;
    PointerActor actor;
    PointerCritic critic;
    torch::optim::Adam optimiser;
    std::uint64_t instanceSeed;
    std::uint64_t updatesDone = 0;

    explicit Impl(const PointerPpoOptions& o)
        : options(o), actor((torch::manual_seed(o.seed), o.hidden)), critic(o.hidden),
          optimiser(parameters(), torch::optim::AdamOptions(o.learningRate)),
          instanceSeed(o.seed * 1000003) {}

    std::vector<torch::Tensor> parameters() {
        std::vector<torch::Tensor> all = actor->parameters();
        for (const torch::Tensor& p : critic->parameters())
            all.push_back(p);
        return all;
    }
};

PointerPpo::PointerPpo(const PointerPpoOptions& options) : impl_(std::make_unique<Impl>(options)) {
    at::set_num_threads(1);
}

PointerPpo::~PointerPpo() = default;

void PointerPpo::train(int updates,
                       const std::function<void(const PointerPpoProgress&)>& progress) {
    Impl& m = *impl_;
    const PointerPpoOptions& o = m.options;
    for (int update = 0; update < updates; ++update) {
        // Torch's sampling generator is global: reseed it per update so that each network
        // is reproducible from its own seed, whatever else ran in between.
        torch::manual_seed(o.seed * 7919 + m.updatesDone++);
        std::vector<tiling::OrderingProblem> problems;
        std::vector<torch::Tensor> inputs;
        for (int k = 0; k < o.batch; ++k) {
            problems.push_back(
                tiling::randomOrderingProblem(o.trainingWaypoints, m.instanceSeed++));
            inputs.push_back(features(problems.back()));
        }
        const torch::Tensor x = torch::stack(inputs);
        torch::Tensor tours, oldLogp;
        {
            torch::NoGradGuard noGrad;
            std::tie(tours, oldLogp) = m.actor->run(x, {}, true);
        }
        torch::Tensor rewards = torch::zeros({o.batch});
        double meanCost = 0.0;
        auto chosen = tours.accessor<int64_t, 2>();
        for (int k = 0; k < o.batch; ++k) {
            tiling::Tour tour{0};
            for (int64_t s = 0; s < tours.size(1); ++s)
                tour.push_back(static_cast<int>(chosen[k][s]));
            const double cost = tiling::tourCost(problems[k], tour);
            meanCost += cost / o.batch;
            // Per waypoint, so rewards are of order one whatever the instance size.
            rewards[k] = static_cast<float>(-cost / costScale(problems[k]) / problems[k].size());
        }
        double criticLoss = 0.0;
        for (int epoch = 0; epoch < o.epochsPerBatch; ++epoch) {
            const torch::Tensor logp = m.actor->run(x, tours, false).second;
            const torch::Tensor value = m.critic->forward(x);
            // Normalised per batch: the critic's early errors must not swamp the actor's step
            // (both share one gradient clip).
            torch::Tensor advantage = rewards - value.detach();
            advantage = (advantage - advantage.mean()) / (advantage.std() + 1e-8);
            const torch::Tensor ratio = torch::exp(logp - oldLogp);
            const torch::Tensor clipped = torch::clamp(ratio, 1.0 - o.clip, 1.0 + o.clip);
            const torch::Tensor actorLoss =
                -torch::min(ratio * advantage, clipped * advantage).mean();
            const torch::Tensor valueLoss = torch::mse_loss(value, rewards);
            m.optimiser.zero_grad();
            (actorLoss + valueLoss).backward();
            torch::nn::utils::clip_grad_norm_(m.parameters(), 1.0);
            m.optimiser.step();
            criticLoss = valueLoss.item<double>();
        }
        if (progress)
            progress({update + 1, meanCost, criticLoss});
    }
}

tiling::Tour PointerPpo::decode(const tiling::OrderingProblem& problem) const {
    tiling::Tour tour{};
    if (problem.size() == 0)
        return tour;
    torch::NoGradGuard noGrad;
    const torch::Tensor tours = impl_->actor->run(features(problem).unsqueeze(0), {}, false).first;
    tour.push_back(0);
    auto chosen = tours.accessor<int64_t, 2>();
    for (int64_t s = 0; s < tours.size(1); ++s)
        tour.push_back(static_cast<int>(chosen[0][s]));
    return tour;
}

void PointerPpo::save(const std::string& path) const {
    torch::serialize::OutputArchive archive;
    impl_->actor->save(archive);
    archive.save_to(path);
}

void PointerPpo::load(const std::string& path) {
    torch::serialize::InputArchive archive;
    archive.load_from(path);
    impl_->actor->load(archive);
}

} // namespace fc
