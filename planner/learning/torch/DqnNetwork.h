// The Q network (internal: included only by the torch translation units of this folder).
#pragma once

#include "learning/torch/DqnAgent.h"

#include <torch/torch.h>

namespace fc {

class QNetworkImpl : public torch::nn::Module {
public:
    QNetworkImpl(int imageSize, int actionCount, const DqnHyperParameters& params);
    // [batch, observationSize] (flat) -> [batch, actionCount]
    torch::Tensor forward(torch::Tensor x);

private:
    torch::Tensor forwardImage(torch::Tensor x);
    torch::Tensor forwardGraph(torch::Tensor x);
    // Message rounds over the valid rows h (owner: their sample, non-decreasing; positions:
    // their features 7 and 8).
    torch::Tensor passMessages(torch::Tensor h, const torch::Tensor& owner,
                               const torch::Tensor& positions, std::int64_t batch);

    QNetworkKind kind_ = QNetworkKind::Convolutional;
    std::int64_t imageSize_ = 0, actionCount_ = 0, channels_ = 0;
    torch::nn::Conv2d conv1_{nullptr}, conv2_{nullptr}, conv3_{nullptr};
    torch::nn::Linear dense1_{nullptr}, dense2_{nullptr};
    // Graph network: per-corner encoder and head (layer names differ from the image
    // network's, so that weights of one never load into the other).
    torch::nn::Linear encode1_{nullptr}, encode2_{nullptr}, head1_{nullptr}, head2_{nullptr},
        context_{nullptr};
    std::int64_t neighbours_ = 0;
    std::vector<torch::nn::Linear> message_, update_;
};
TORCH_MODULE(QNetwork);

// target <- source, parameters and buffers (same architecture), without recording gradients.
void copyWeights(QNetwork& source, QNetwork& target);

} // namespace fc
