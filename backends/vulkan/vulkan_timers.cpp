// Timers: a pair of timestamp queries per timer in one query pool, or the wall clock around a
// submit where the queue has no timestamps (timestampValidBits 0).
#include "vulkan_device_impl.hpp"

namespace sfx::vulkan {

Status VulkanDevice::createTimerPool() {
    if (timestampValidBits_ > 0) {
        VkQueryPoolCreateInfo qci{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        qci.queryType = VK_QUERY_TYPE_TIMESTAMP;
        qci.queryCount = kMaxTimers * 2;
        SFX_VK(vk_.vkCreateQueryPool(device_, &qci, nullptr, &queryPool_));
    }
    for (uint32_t i = kMaxTimers; i > 0; --i) freeTimerSlots_.push_back(i - 1);
    return Status::ok();
}

void VulkanDevice::markEndedTimersFlushed(bool hostRecorded, double wallMs) {
    timers_.forEachAlive([&](VulkanTimer& t) {
        if (t.state == VulkanTimer::State::Ended) {
            t.state = VulkanTimer::State::Flushed;
            if (!hostRecorded) t.wallMs = wallMs;
            t.hostRecorded = hostRecorded;
        }
    });
}

Result<TimerHandle> VulkanDevice::doCreateTimer() {
    if (freeTimerSlots_.empty())
        // Vulkan only: timers are query pairs in one pool of fixed size (GL and null have no pool).
        return validation::fail(validation::Error::TimerPoolFull, {std::to_string(kMaxTimers)});
    VulkanTimer t;
    t.queryIndex = freeTimerSlots_.back() * 2;
    freeTimerSlots_.pop_back();
    return timers_.insert(t);
}

Status VulkanDevice::doDestroyTimer(TimerHandle h) {
    freeTimerSlots_.push_back(timers_.remove(h).queryIndex / 2);
    return Status::ok();
}

Status VulkanDevice::doBeginTimer(TimerHandle h) {
    if (noteTimer()) return Status::ok();
    VulkanTimer& t = timers_.get(h);
    Result<VkCommandBuffer> cb = recording();
    if (!cb) return cb.status();
    if (queryPool_) {
        vk_.vkCmdResetQueryPool(cb.value(), queryPool_, t.queryIndex, 2);
        vk_.vkCmdWriteTimestamp(cb.value(), VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, queryPool_, t.queryIndex);
    }
    t.state = VulkanTimer::State::Begun;
    return Status::ok();
}

Status VulkanDevice::doEndTimer(TimerHandle h) {
    if (noteTimer()) return Status::ok();
    VulkanTimer& t = timers_.get(h);
    if (t.state != VulkanTimer::State::Begun) return validation::fail(validation::Error::TimerNotBegun, {});
    Result<VkCommandBuffer> cb = recording();
    if (!cb) return cb.status();
    if (queryPool_) vk_.vkCmdWriteTimestamp(cb.value(), VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, queryPool_, t.queryIndex + 1);
    t.state = VulkanTimer::State::Ended;
    return Status::ok();
}

Result<TimerReading> VulkanDevice::doReadTimer(TimerHandle h) {
    VulkanTimer& t = timers_.get(h);
    if (t.state != VulkanTimer::State::Flushed) return validation::fail(validation::Error::TimerNoMeasurement, {});
    if (!queryPool_) return TimerReading{t.wallMs, TimingSource::WallClockAfterFinish};
    uint64_t stamps[2] = {0, 0};
    // A host command buffer may not have run yet: never wait for it.
    const VkQueryResultFlags flags = VK_QUERY_RESULT_64_BIT | (t.hostRecorded ? 0 : VK_QUERY_RESULT_WAIT_BIT);
    VkResult r = vk_.vkGetQueryPoolResults(device_, queryPool_, t.queryIndex, 2, sizeof(stamps), stamps, sizeof(uint64_t), flags);
    if (r == VK_NOT_READY)
        // Vulkan only: only the Vulkan backend records into a host's command buffer.
        return validation::fail(validation::Error::TimerHostPending, {});
    if (r != VK_SUCCESS) return vkError("vkGetQueryPoolResults", r);
    const uint64_t mask = timestampValidBits_ >= 64 ? ~uint64_t(0) : ((uint64_t(1) << timestampValidBits_) - 1);
    const uint64_t ticks = (stamps[1] - stamps[0]) & mask;
    return TimerReading{double(ticks) * double(props_.limits.timestampPeriod) * 1e-6, TimingSource::GpuTimestamps};
}

}  // namespace sfx::vulkan
