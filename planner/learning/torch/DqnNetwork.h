// The Q network (internal: included only by the torch translation units of this folder).
#pragma once

#include "learning/torch/DqnAgent.h"

#include <torch/torch.h>

namespace fc {

class QNetworkImpl : public torch::nn::Module {
public:
    QNetworkImpl(int imageSize, int actionCount, const DqnHyperParameters& params);
    // [batch, 3, SIZE, SIZE] -> [batch, actionCount]
    torch::Tensor forward(torch::Tensor x);

private:
    torch::nn::Conv2d conv1_{nullptr}, conv2_{nullptr}, conv3_{nullptr};
    torch::nn::Linear dense1_{nullptr}, dense2_{nullptr};
};
TORCH_MODULE(QNetwork);

// target <- source, parameters and buffers (same architecture), without recording gradients.
void copyWeights(QNetwork& source, QNetwork& target);

} // namespace fc
