#include "learning/torch/DqnNetwork.h"

#include <stdexcept>

namespace fc {

namespace {

torch::nn::Conv2d conv(int in, int out) {
    return torch::nn::Conv2d(torch::nn::Conv2dOptions(in, out, 3).stride(1).padding(1));
}

} // namespace

QNetworkImpl::QNetworkImpl(int imageSize, int actionCount, const DqnHyperParameters& params) {
    if (imageSize <= 0 || actionCount <= 0)
        throw std::invalid_argument("QNetwork: image size and action count must be positive");
    conv1_ = register_module("conv1", conv(params.inputChannels, params.conv1Channels));
    conv2_ = register_module("conv2", conv(params.conv1Channels, params.conv2Channels));
    conv3_ = register_module("conv3", conv(params.conv2Channels, params.conv3Channels));
    const std::int64_t flat =
        static_cast<std::int64_t>(params.conv3Channels) * imageSize * imageSize;
    dense1_ = register_module("dense1", torch::nn::Linear(flat, params.hiddenUnits));
    dense2_ = register_module("dense2", torch::nn::Linear(params.hiddenUnits, actionCount));
}

torch::Tensor QNetworkImpl::forward(torch::Tensor x) {
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
