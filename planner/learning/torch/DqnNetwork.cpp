#include "learning/torch/DqnNetwork.h"

#include "learning/NearestCorners.h"

#include <algorithm>
#include <stdexcept>

namespace fc {

namespace {

torch::nn::Conv2d conv(int in, int out) {
    return torch::nn::Conv2d(torch::nn::Conv2dOptions(in, out, 3).stride(1).padding(1));
}

} // namespace

QNetworkImpl::QNetworkImpl(int imageSize, int actionCount, const DqnHyperParameters& params)
    : kind_(params.network), imageSize_(imageSize), actionCount_(actionCount),
      channels_(params.inputChannels) {
    if (imageSize <= 0 || actionCount <= 0)
        throw std::invalid_argument("QNetwork: image size and action count must be positive");
    if (kind_ == QNetworkKind::Graph) {
        const std::int64_t hidden = params.hiddenUnits;
        encode1_ = register_module("encode1", torch::nn::Linear(channels_, hidden));
        encode2_ = register_module("encode2", torch::nn::Linear(hidden, hidden));
        head1_ = register_module("head1", torch::nn::Linear(hidden, hidden));
        context_ = register_module(
            "context", torch::nn::Linear(torch::nn::LinearOptions(2 * hidden, hidden).bias(false)));
        head2_ = register_module("head2", torch::nn::Linear(hidden, 1));
        if (params.messageRounds < 0 || params.messageNeighbours < 1)
            throw std::invalid_argument("QNetwork: message rounds or neighbours out of range");
        if (params.messageRounds > 0 && channels_ < 9)
            throw std::invalid_argument("QNetwork: messages need the corners' positions "
                                        "(graph features 7 and 8)");
        neighbours_ = params.messageNeighbours;
        for (int r = 0; r < params.messageRounds; ++r) {
            const std::string round = std::to_string(r);
            message_.push_back(
                register_module("message" + round, torch::nn::Linear(hidden + 3, hidden)));
            update_.push_back(
                register_module("update" + round, torch::nn::Linear(2 * hidden, hidden)));
        }
        return;
    }
    conv1_ = register_module("conv1", conv(params.inputChannels, params.conv1Channels));
    conv2_ = register_module("conv2", conv(params.conv1Channels, params.conv2Channels));
    conv3_ = register_module("conv3", conv(params.conv2Channels, params.conv3Channels));
    const std::int64_t flat =
        static_cast<std::int64_t>(params.conv3Channels) * imageSize * imageSize;
    dense1_ = register_module("dense1", torch::nn::Linear(flat, params.hiddenUnits));
    dense2_ = register_module("dense2", torch::nn::Linear(params.hiddenUnits, actionCount));
}

torch::Tensor QNetworkImpl::forward(torch::Tensor x) {
    return kind_ == QNetworkKind::Graph ? forwardGraph(x) : forwardImage(x);
}

// Only the valid corners (feature 0) are encoded and scored: the others are never chosen
// (masked acting and argmax) and get Q = 0. Rows of all samples are stacked, so the cost
// follows the valid corners of the batch, not batch x corners.
// The corner count comes from the input, not the constructor: the weights are shared by all
// corners, so one network scores graphs of any size (a generalist model; batches of several
// graphs are padded with invalid corners).
torch::Tensor QNetworkImpl::forwardGraph(torch::Tensor x) {
    const std::int64_t batch = x.size(0);
    const std::int64_t corners = x.size(1) / channels_;
    const torch::Tensor flat = x.reshape({batch * corners, channels_});
    const torch::Tensor rows = (flat.select(1, 0) > 0.5f).nonzero().squeeze(1);
    const torch::Tensor owner = torch::div(rows, corners, "floor");
    torch::Tensor h = torch::relu(encode1_->forward(flat.index_select(0, rows)));
    h = torch::relu(encode2_->forward(h)); // [valid rows, hidden]
    if (!message_.empty() && rows.size(0) > 0)
        h = passMessages(h, owner, flat.index_select(0, rows).slice(1, 7, 9), batch);
    const std::int64_t hidden = h.size(1);
    const torch::Tensor sum = torch::zeros({batch, hidden}).index_add(0, owner, h);
    const torch::Tensor count =
        torch::zeros({batch}).index_add(0, owner, torch::ones({rows.size(0)})).clamp_min(1.0f);
    // Encodings are >= 0 (ReLU), so zeros stand in for the other corners in the max.
    const torch::Tensor max = std::get<0>(torch::zeros({batch * corners, hidden})
                                              .index_copy(0, rows, h)
                                              .reshape({batch, corners, hidden})
                                              .max(1));
    const torch::Tensor context =
        context_->forward(torch::cat({sum / count.unsqueeze(1), max}, 1)); // [batch, hidden]
    torch::Tensor q = torch::relu(head1_->forward(h) + context.index_select(0, owner));
    q = head2_->forward(q).squeeze(1);
    return torch::zeros({batch * corners}).index_copy(0, rows, q).reshape({batch, corners});
}

// The neighbours of each valid row are found per sample (rows of one sample are contiguous:
// `owner` is non-decreasing), among that sample's rows only, by straight-line distance
// (learning/NearestCorners); a sample with fewer rows than neighbours_ repeats the row
// itself, which the max ignores.
torch::Tensor QNetworkImpl::passMessages(torch::Tensor h, const torch::Tensor& owner,
                                         const torch::Tensor& positions, std::int64_t batch) {
    const std::int64_t rows = h.size(0);
    torch::Tensor neighbour, offset;
    {
        torch::NoGradGuard noGrad;
        const torch::Tensor counts = torch::bincount(owner, {}, batch);
        const auto* count = counts.data_ptr<std::int64_t>();
        const torch::Tensor xy = positions.contiguous();
        const int k = static_cast<int>(neighbours_);
        std::vector<std::int64_t> indices(static_cast<std::size_t>(rows * neighbours_));
        std::vector<float> scales(static_cast<std::size_t>(rows));
        std::int64_t first = 0;
        for (std::int64_t b = 0; b < batch; ++b) {
            const std::int64_t n = count[b];
            if (n == 0)
                continue;
            const NearestCorners near =
                nearestCorners(xy.data_ptr<float>() + 2 * first, static_cast<int>(n), k);
            for (std::size_t i = 0; i < near.index.size(); ++i)
                indices[static_cast<std::size_t>(first * neighbours_) + i] = near.index[i] + first;
            std::fill_n(scales.begin() + first, n,
                        static_cast<float>(std::max(near.meanDistance, 1e-6)));
            first += n;
        }
        neighbour = torch::from_blob(indices.data(), {rows * neighbours_}, torch::kInt64).clone();
        const torch::Tensor scale =
            torch::from_blob(scales.data(), {rows, 1, 1}, torch::kFloat32).clone();
        offset = (xy.index_select(0, neighbour).reshape({rows, neighbours_, 2}) - xy.unsqueeze(1)) /
                 scale;
        offset = torch::cat({offset, offset.norm(2, 2, true)}, 2); // and the distance
    }
    for (std::size_t r = 0; r < message_.size(); ++r) {
        const torch::Tensor from =
            h.index_select(0, neighbour).reshape({rows, neighbours_, h.size(1)});
        const torch::Tensor message =
            torch::relu(message_[r]->forward(torch::cat({from, offset}, 2)));
        const torch::Tensor pooled = std::get<0>(message.max(1)); // [rows, hidden]
        h = h + torch::relu(update_[r]->forward(torch::cat({h, pooled}, 1)));
    }
    return h;
}

torch::Tensor QNetworkImpl::forwardImage(torch::Tensor x) {
    x = x.reshape({-1, channels_, imageSize_, imageSize_});
    x = torch::relu(conv1_->forward(x));
    x = torch::relu(conv2_->forward(x));
    x = torch::relu(conv3_->forward(x));
    x = x.flatten(1);
    x = torch::relu(dense1_->forward(x));
    return dense2_->forward(x);
}

void copyWeights(QNetwork& source, QNetwork& target) {
    torch::NoGradGuard noGrad;
    const auto from = source->named_parameters(true);
    auto to = target->named_parameters(true);
    for (const auto& item : from)
        to[item.key()].copy_(item.value());
    const auto fromBuffers = source->named_buffers(true);
    auto toBuffers = target->named_buffers(true);
    for (const auto& item : fromBuffers)
        toBuffers[item.key()].copy_(item.value());
}

} // namespace fc
