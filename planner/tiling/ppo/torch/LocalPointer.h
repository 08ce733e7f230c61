// The local pointer network of PointerPpo (internal: torch types). Candidates [N, K, F] are
// embedded and read by an LSTM encoder; an LSTM decoder cell reads the features of each
// move made; additive attention of the decoder state over the encoded candidates gives the
// move logits; the critic reads the decoder state and the mean encoded candidate.
#pragma once

#include <torch/torch.h>

namespace fc {

struct LocalPointerImpl : torch::nn::Module {
    LocalPointerImpl(int features, int hidden);

    // Encoded candidates and attention keys, [N, K, H] each.
    std::pair<torch::Tensor, torch::Tensor> encode(const torch::Tensor& candidates);
    // One decoder step on the last move's features [B, F].
    std::tuple<torch::Tensor, torch::Tensor>
    decode(const torch::Tensor& lastMove, const std::tuple<torch::Tensor, torch::Tensor>& state);
    // Masked log-probabilities over the slots [N, K] (mask true where a candidate is).
    torch::Tensor logProbabilities(const torch::Tensor& keys, const torch::Tensor& query,
                                   const torch::Tensor& mask);
    torch::Tensor value(const torch::Tensor& encoded, const torch::Tensor& query,
                        const torch::Tensor& mask);

    int hidden;
    torch::nn::Linear embed{nullptr}, moveEmbed{nullptr};
    torch::nn::LSTM encoder{nullptr};
    torch::nn::LSTMCell decoder{nullptr};
    torch::nn::Linear attendEncoded{nullptr}, attendQuery{nullptr};
    torch::Tensor attendVector;
    torch::nn::Linear criticHidden{nullptr}, criticOut{nullptr};
};
TORCH_MODULE(LocalPointer);

} // namespace fc
