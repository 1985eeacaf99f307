#include "vulkan_compute.hpp"

#include <cstring>
#include <stdexcept>

#include <vulkan/vulkan.h>

namespace brdftab::gpu_test {

namespace {
void check(VkResult r, const char* what) {
  if (r != VK_SUCCESS) throw std::runtime_error(std::string(what) + " failed (VkResult " + std::to_string(r) + ")");
}
}  // namespace

struct VulkanCompute::Impl {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  std::uint32_t family = 0;
  VkPhysicalDeviceMemoryProperties memory{};

  struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
  };
  Buffer make_buffer(VkDeviceSize size) {
    Buffer b;
    b.size = size;
    VkBufferCreateInfo bi{};
    bi.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    bi.size = size;
    bi.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    bi.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    check(vkCreateBuffer(device, &bi, nullptr, &b.buffer), "vkCreateBuffer");
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device, b.buffer, &req);
    const VkMemoryPropertyFlags want = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    std::uint32_t type = UINT32_MAX;
    for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i)
      if ((req.memoryTypeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & want) == want) {
        type = i;
        break;
      }
    if (type == UINT32_MAX) throw std::runtime_error("no host-visible coherent memory type");
    VkMemoryAllocateInfo ai{};
    ai.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    ai.allocationSize = req.size;
    ai.memoryTypeIndex = type;
    check(vkAllocateMemory(device, &ai, nullptr, &b.memory), "vkAllocateMemory");
    check(vkBindBufferMemory(device, b.buffer, b.memory, 0), "vkBindBufferMemory");
    return b;
  }
  void write(const Buffer& b, const void* data, std::size_t bytes) {
    void* p = nullptr;
    check(vkMapMemory(device, b.memory, 0, b.size, 0, &p), "vkMapMemory");
    std::memcpy(p, data, bytes);
    vkUnmapMemory(device, b.memory);
  }
  void free(Buffer& b) {
    if (b.buffer) vkDestroyBuffer(device, b.buffer, nullptr);
    if (b.memory) vkFreeMemory(device, b.memory, nullptr);
    b = {};
  }
};

VulkanCompute::VulkanCompute() : impl_(new Impl) {
  try {
    VkApplicationInfo app{};
    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.pApplicationName = "brdftab_glsl_vulkan_test";
    app.apiVersion = VK_API_VERSION_1_1;
    VkInstanceCreateInfo ii{};
    ii.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    ii.pApplicationInfo = &app;
    check(vkCreateInstance(&ii, nullptr, &impl_->instance),
          "vkCreateInstance (no Vulkan driver? install mesa-vulkan-drivers and set VK_ICD_FILENAMES to lavapipe's lvp_icd json)");
    std::uint32_t n = 0;
    check(vkEnumeratePhysicalDevices(impl_->instance, &n, nullptr), "vkEnumeratePhysicalDevices");
    if (n == 0) throw std::runtime_error("no Vulkan device (is VK_ICD_FILENAMES set to lavapipe's lvp_icd json?)");
    std::vector<VkPhysicalDevice> devices(n);
    check(vkEnumeratePhysicalDevices(impl_->instance, &n, devices.data()), "vkEnumeratePhysicalDevices");
    impl_->physical = devices[0];
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(impl_->physical, &props);
    device_name_ = props.deviceName;
    is_cpu_ = props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    vkGetPhysicalDeviceMemoryProperties(impl_->physical, &impl_->memory);
    std::uint32_t nq = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(impl_->physical, &nq, nullptr);
    std::vector<VkQueueFamilyProperties> qf(nq);
    vkGetPhysicalDeviceQueueFamilyProperties(impl_->physical, &nq, qf.data());
    impl_->family = UINT32_MAX;
    for (std::uint32_t i = 0; i < nq; ++i)
      if (qf[i].queueFlags & VK_QUEUE_COMPUTE_BIT) {
        impl_->family = i;
        break;
      }
    if (impl_->family == UINT32_MAX) throw std::runtime_error("device '" + device_name_ + "' has no compute queue");
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo qi{};
    qi.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    qi.queueFamilyIndex = impl_->family;
    qi.queueCount = 1;
    qi.pQueuePriorities = &priority;
    VkDeviceCreateInfo di{};
    di.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    di.queueCreateInfoCount = 1;
    di.pQueueCreateInfos = &qi;
    check(vkCreateDevice(impl_->physical, &di, nullptr, &impl_->device), "vkCreateDevice");
    vkGetDeviceQueue(impl_->device, impl_->family, 0, &impl_->queue);
  } catch (...) {
    if (impl_->device) vkDestroyDevice(impl_->device, nullptr);
    if (impl_->instance) vkDestroyInstance(impl_->instance, nullptr);
    delete impl_;
    throw;
  }
}

VulkanCompute::~VulkanCompute() {
  vkDestroyDevice(impl_->device, nullptr);
  vkDestroyInstance(impl_->instance, nullptr);
  delete impl_;
}

std::vector<float> VulkanCompute::run(const std::vector<std::uint32_t>& spirv, const std::vector<float>& values,
                                      const std::vector<float>& inputs, std::size_t n_out) {
  Impl& v = *impl_;
  VkDevice dev = v.device;
  Impl::Buffer buf[3] = {v.make_buffer(values.size() * 4), v.make_buffer(inputs.size() * 4), v.make_buffer(n_out * 4)};
  v.write(buf[0], values.data(), values.size() * 4);
  v.write(buf[1], inputs.data(), inputs.size() * 4);

  VkShaderModuleCreateInfo si{};

  si.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
  si.codeSize = spirv.size() * 4;
  si.pCode = spirv.data();
  VkShaderModule module;
  check(vkCreateShaderModule(dev, &si, nullptr, &module), "vkCreateShaderModule");
  VkDescriptorSetLayoutBinding bindings[3]{};
  for (std::uint32_t i = 0; i < 3; ++i) {
    bindings[i].binding = i;
    bindings[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    bindings[i].descriptorCount = 1;
    bindings[i].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
  }
  VkDescriptorSetLayoutCreateInfo li{};
  li.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  li.bindingCount = 3;
  li.pBindings = bindings;
  VkDescriptorSetLayout set_layout;
  check(vkCreateDescriptorSetLayout(dev, &li, nullptr, &set_layout), "vkCreateDescriptorSetLayout");
  VkPipelineLayoutCreateInfo pli{};
  pli.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  pli.setLayoutCount = 1;
  pli.pSetLayouts = &set_layout;
  VkPipelineLayout layout;
  check(vkCreatePipelineLayout(dev, &pli, nullptr, &layout), "vkCreatePipelineLayout");
  VkComputePipelineCreateInfo ci{};
  ci.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
  ci.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  ci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  ci.stage.module = module;
  ci.stage.pName = "main";
  ci.layout = layout;
  VkPipeline pipeline;
  check(vkCreateComputePipelines(dev, VK_NULL_HANDLE, 1, &ci, nullptr, &pipeline), "vkCreateComputePipelines");
  VkDescriptorPoolSize ps{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 3};
  VkDescriptorPoolCreateInfo pi{};
  pi.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  pi.maxSets = 1;
  pi.poolSizeCount = 1;
  pi.pPoolSizes = &ps;
  VkDescriptorPool pool;
  check(vkCreateDescriptorPool(dev, &pi, nullptr, &pool), "vkCreateDescriptorPool");
  VkDescriptorSetAllocateInfo dai{};
  dai.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  dai.descriptorPool = pool;
  dai.descriptorSetCount = 1;
  dai.pSetLayouts = &set_layout;
  VkDescriptorSet set;
  check(vkAllocateDescriptorSets(dev, &dai, &set), "vkAllocateDescriptorSets");
  VkDescriptorBufferInfo info[3];
  VkWriteDescriptorSet writes[3]{};
  for (int i = 0; i < 3; ++i) {
    info[i] = {buf[i].buffer, 0, VK_WHOLE_SIZE};
    writes[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    writes[i].dstSet = set;
    writes[i].dstBinding = static_cast<std::uint32_t>(i);
    writes[i].descriptorCount = 1;
    writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[i].pBufferInfo = &info[i];
  }
  vkUpdateDescriptorSets(dev, 3, writes, 0, nullptr);
  VkCommandPoolCreateInfo cpi{};
  cpi.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
  cpi.queueFamilyIndex = v.family;
  VkCommandPool cpool;
  check(vkCreateCommandPool(dev, &cpi, nullptr, &cpool), "vkCreateCommandPool");
  VkCommandBufferAllocateInfo cai{};
  cai.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
  cai.commandPool = cpool;
  cai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  cai.commandBufferCount = 1;
  VkCommandBuffer cmd;
  check(vkAllocateCommandBuffers(dev, &cai, &cmd), "vkAllocateCommandBuffers");
  VkCommandBufferBeginInfo bi{};
  bi.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(cmd, &bi), "vkBeginCommandBuffer");
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, 1, &set, 0, nullptr);
  vkCmdDispatch(cmd, static_cast<std::uint32_t>((n_out + 63) / 64), 1, 1);
  VkMemoryBarrier mb{};
  mb.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
  mb.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  mb.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &mb, 0, nullptr, 0,
                       nullptr);
  check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
  VkFenceCreateInfo fi{};
  fi.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
  VkFence fence;
  check(vkCreateFence(dev, &fi, nullptr, &fence), "vkCreateFence");
  VkSubmitInfo sub{};
  sub.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
  sub.commandBufferCount = 1;
  sub.pCommandBuffers = &cmd;
  check(vkQueueSubmit(v.queue, 1, &sub, fence), "vkQueueSubmit");
  check(vkWaitForFences(dev, 1, &fence, VK_TRUE, UINT64_C(60000000000)), "vkWaitForFences");

  std::vector<float> out(n_out);
  void* p = nullptr;
  check(vkMapMemory(dev, buf[2].memory, 0, buf[2].size, 0, &p), "vkMapMemory");
  std::memcpy(out.data(), p, n_out * 4);
  vkUnmapMemory(dev, buf[2].memory);

  vkDestroyFence(dev, fence, nullptr);
  vkDestroyCommandPool(dev, cpool, nullptr);
  vkDestroyDescriptorPool(dev, pool, nullptr);
  vkDestroyPipeline(dev, pipeline, nullptr);
  vkDestroyPipelineLayout(dev, layout, nullptr);
  vkDestroyDescriptorSetLayout(dev, set_layout, nullptr);
  vkDestroyShaderModule(dev, module, nullptr);
  for (auto& b : buf) v.free(b);
  return out;
}

}  // namespace brdftab::gpu_test
