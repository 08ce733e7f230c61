#include "tiling/ppo/torch/LocalPointer.h"

namespace fc {

LocalPointerImpl::LocalPointerImpl(int features, int size) : hidden(size) {
    embed = register_module("embed", torch::nn::Linear(features, size));
    moveEmbed = register_module("move_embed", torch::nn::Linear(features, size));
    encoder = register_module(
        "encoder", torch::nn::LSTM(torch::nn::LSTMOptions(size, size).batch_first(true)));
    decoder = register_module("decoder", torch::nn::LSTMCell(size, size));
    attendEncoded = register_module("attend_encoded", torch::nn::Linear(size, size));
    attendQuery = register_module("attend_query", torch::nn::Linear(size, size));
    attendVector = register_parameter("attend_vector", torch::randn({size}) * 0.1);
    criticHidden = register_module("critic_hidden", torch::nn::Linear(2 * size, size));
    criticOut = register_module("critic_out", torch::nn::Linear(size, 1));
}

std::pair<torch::Tensor, torch::Tensor> LocalPointerImpl::encode(const torch::Tensor& candidates) {
    torch::Tensor encoded = std::get<0>(encoder->forward(torch::relu(embed->forward(candidates))));
    return {encoded, attendEncoded->forward(encoded)};
}

std::tuple<torch::Tensor, torch::Tensor>
LocalPointerImpl::decode(const torch::Tensor& lastMove,
                         const std::tuple<torch::Tensor, torch::Tensor>& state) {
    return decoder->forward(torch::relu(moveEmbed->forward(lastMove)), state);
}

torch::Tensor LocalPointerImpl::logProbabilities(const torch::Tensor& keys,
                                                 const torch::Tensor& query,
                                                 const torch::Tensor& mask) {
    torch::Tensor scores =
        torch::tanh(keys + attendQuery->forward(query).unsqueeze(1)).matmul(attendVector);
    scores = 10.0 * torch::tanh(scores); // clipped logits (Bello et al.)
    return torch::log_softmax(scores.masked_fill(mask.logical_not(), -1e9), 1);
}

torch::Tensor LocalPointerImpl::value(const torch::Tensor& encoded, const torch::Tensor& query,
                                      const torch::Tensor& mask) {
    const torch::Tensor weights = mask.to(torch::kFloat).unsqueeze(2);
    const torch::Tensor mean = (encoded * weights).sum(1) / weights.sum(1).clamp_min(1.0);
    const torch::Tensor joint = torch::cat({query, mean}, 1);
    return criticOut->forward(torch::relu(criticHidden->forward(joint))).squeeze(1);
}

} // namespace fc
