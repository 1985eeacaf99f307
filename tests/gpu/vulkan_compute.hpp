#pragma once
// A minimal Vulkan compute runner for the GLSL export test: one SPIR-V compute shader with
// three storage buffers (binding 0: the table values, 1: the input points, 2: the outputs),
// dispatched once. Throws std::runtime_error naming the failing call.
#include <cstdint>
#include <string>
#include <vector>

namespace brdftab::gpu_test {

class VulkanCompute {
 public:
  VulkanCompute();  // instance, first device, a compute queue
  ~VulkanCompute();
  VulkanCompute(const VulkanCompute&) = delete;
  VulkanCompute& operator=(const VulkanCompute&) = delete;
  const std::string& device_name() const { return device_name_; }
  bool is_cpu() const { return is_cpu_; }
  // Runs `spirv` with local size 64 over ceil(n_out / 64) groups.
  std::vector<float> run(const std::vector<std::uint32_t>& spirv, const std::vector<float>& values,
                         const std::vector<float>& inputs, std::size_t n_out);

 private:
  struct Impl;
  Impl* impl_;
  std::string device_name_;
  bool is_cpu_ = false;
};

}  // namespace brdftab::gpu_test
