// The cartoon pipelines of "Unity SRP for cartoon style rendering optimisations":
//  cartoon            one MRT render pass (colour, normals, border colour, depth), then a
//                     full-screen Sobel-edge blit compositing edges with the border colours;
//  cartoon-multipass  the same image the naive way: one pass per buffer, then the same blit
//                     (bit-identical image; only time and traffic differ);
//  cartoon-hull       toon environment shading plus inverted-hull outlines, no screen pass.
// Options (--set): normals=rgb10a2|rgba16f (cartoon, cartoon-multipass).
#pragma once
#include "pipelines/kit/pipeline.h"

namespace ontile {

class CartoonPipeline final : public Pipeline {
 public:
  explicit CartoonPipeline(bool multipass) : multipass_(multipass) {}
  std::string name() const override { return multipass_ ? "cartoon-multipass" : "cartoon"; }
  std::string description() const override {
    return multipass_ ? "cartoon image the naive way: one pass per G-buffer target, then Sobel edges"
                      : "cartoon MRT pass (colour, normals, border, depth) + Sobel edge blit";
  }
  FrameOutputs render(RenderContext& context, const FrameInputs& inputs) override;

 private:
  bool multipass_;
};

class CartoonHullPipeline final : public Pipeline {
 public:
  std::string name() const override { return "cartoon-hull"; }
  std::string description() const override {
    return "toon environment shading + inverted-hull outlines, one forward pass";
  }
  FrameOutputs render(RenderContext& context, const FrameInputs& inputs) override;
};

}  // namespace ontile
