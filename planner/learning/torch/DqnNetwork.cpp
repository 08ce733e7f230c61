#include "learning/torch/DqnNetwork.h"

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
        head1_ = register_module("head1", torch::nn::Linear(3 * hidden, hidden));
        head2_ = register_module("head2", torch::nn::Linear(hidden, 1));
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

torch::Tensor QNetworkImpl::forwardGraph(torch::Tensor x) {
    x = x.reshape({-1, actionCount_, channels_});
    const torch::Tensor valid = x.narrow(2, 0, 1); // [batch, corners, 1]
    torch::Tensor h = torch::relu(encode1_->forward(x));
    h = torch::relu(encode2_->forward(h));
    // Context over the valid corners (all corners when none is valid: a finished episode).
    const torch::Tensor count = valid.sum(1, /*keepdim=*/true);
    const torch::Tensor weight = torch::where(count > 0, valid, torch::ones_like(valid));
    const torch::Tensor mean = (h * weight).sum(1) / weight.sum(1);
    const torch::Tensor max = std::get<0>((h * weight).max(1));
    const torch::Tensor context =
        torch::cat({mean, max}, 1).unsqueeze(1).expand({h.size(0), actionCount_, 2 * h.size(2)});
    torch::Tensor q = torch::relu(head1_->forward(torch::cat({h, context}, 2)));
    return head2_->forward(q).squeeze(2);
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
