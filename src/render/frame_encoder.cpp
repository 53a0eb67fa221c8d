// The PNG encoder pool: see frame_encoder.h.
#include "render/frame_encoder.h"

#include <algorithm>

#include <fmt/core.h>

#include "render/png_writer.h"

namespace polyroll::render {

std::string frame_file_name(long index) { return fmt::format("frame_{:06d}.png", index); }

FrameEncoder::FrameEncoder(std::filesystem::path dir, int threads, int queue_capacity)
    : dir_(std::move(dir)), capacity_(static_cast<size_t>(std::max(1, queue_capacity))) {
    for (int i = 0; i < std::max(1, threads); ++i) workers_.emplace_back([this] { work(); });
}

FrameEncoder::~FrameEncoder() {
    {
        std::lock_guard<std::mutex> lock(mu_);
        stopping_ = true;
        queue_.clear();
    }
    not_empty_.notify_all();
    not_full_.notify_all();
    for (std::thread& t : workers_) t.join();
}

std::vector<std::uint8_t> FrameEncoder::take_buffer(size_t bytes) {
    std::vector<std::uint8_t> b;
    {
        std::lock_guard<std::mutex> lock(mu_);
        if (!spare_.empty()) {
            b = std::move(spare_.back());
            spare_.pop_back();
        }
    }
    b.resize(bytes);
    return b;
}

void FrameEncoder::rethrow_locked() {
    if (error_) std::rethrow_exception(error_);
}

void FrameEncoder::submit(long first_index, int copies, ImageView format, std::vector<std::uint8_t> pixels) {
    std::unique_lock<std::mutex> lock(mu_);
    not_full_.wait(lock, [&] { return queue_.size() < capacity_ || error_ || stopping_; });
    rethrow_locked();
    queue_.push_back({first_index, copies, format, std::move(pixels)});
    lock.unlock();
    not_empty_.notify_one();
}

void FrameEncoder::finish() {
    std::unique_lock<std::mutex> lock(mu_);
    idle_.wait(lock, [&] { return (queue_.empty() && busy_ == 0) || error_; });
    rethrow_locked();
}

long FrameEncoder::frames_written() const {
    std::lock_guard<std::mutex> lock(mu_);
    return frames_written_;
}

std::uint64_t FrameEncoder::bytes_written() const {
    std::lock_guard<std::mutex> lock(mu_);
    return bytes_written_;
}

void FrameEncoder::work() {
    for (;;) {
        Job job;
        {
            std::unique_lock<std::mutex> lock(mu_);
            not_empty_.wait(lock, [&] { return !queue_.empty() || stopping_; });
            if (stopping_) return;
            job = std::move(queue_.front());
            queue_.pop_front();
            ++busy_;
        }
        not_full_.notify_one();
        std::uint64_t bytes = 0;
        try {
            ImageView image = job.format;
            image.pixels = job.pixels.data();
            const std::vector<std::uint8_t> png = encode_png(image);
            for (int c = 0; c < job.copies; ++c) {
                write_file_whole(dir_ / frame_file_name(job.first_index + c), png);
                bytes += png.size();
            }
        } catch (...) {
            std::lock_guard<std::mutex> lock(mu_);
            if (!error_) error_ = std::current_exception();
        }
        {
            std::lock_guard<std::mutex> lock(mu_);
            --busy_;
            if (bytes > 0) frames_written_ += job.copies;
            bytes_written_ += bytes;
            spare_.push_back(std::move(job.pixels));
        }
        idle_.notify_all();
        not_full_.notify_all();
    }
}

}  // namespace polyroll::render
