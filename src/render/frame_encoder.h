// Encodes and writes frames on a small pool of threads behind a bounded queue, so PNG compression
// overlaps simulating and drawing the next frames. A full queue makes submit() wait: memory stays
// bounded however far the renderer runs ahead. The first error a worker meets is rethrown to the
// caller by the next submit() or by finish().
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "render/png_writer.h"

namespace polyroll::render {

// frame_000001.png for index 1: the name of a frame in a sequence.
std::string frame_file_name(long index);

class FrameEncoder {
public:
    FrameEncoder(std::filesystem::path dir, int threads, int queue_capacity);
    ~FrameEncoder();  // stops the workers; call finish() first to keep their work
    FrameEncoder(const FrameEncoder&) = delete;
    FrameEncoder& operator=(const FrameEncoder&) = delete;

    // A buffer for a frame's pixels (recycled from frames already written).
    std::vector<std::uint8_t> take_buffer(size_t bytes);

    // Queues one image (`pixels` in the layout `format` describes; its pointer is ignored) to be
    // written as frames first_index .. first_index + copies - 1: a held final state is encoded once
    // and written as many times as it is shown.
    void submit(long first_index, int copies, ImageView format, std::vector<std::uint8_t> pixels);

    // Waits until every queued frame is on disk; rethrows a worker's error.
    void finish();

    long frames_written() const;
    std::uint64_t bytes_written() const;

private:
    struct Job {
        long first_index = 0;
        int copies = 1;
        ImageView format;
        std::vector<std::uint8_t> pixels;
    };
    void work();
    void rethrow_locked();

    std::filesystem::path dir_;
    size_t capacity_;
    mutable std::mutex mu_;
    std::condition_variable not_full_, not_empty_, idle_;
    std::deque<Job> queue_;
    std::vector<std::vector<std::uint8_t>> spare_;
    int busy_ = 0;
    bool stopping_ = false;
    std::exception_ptr error_;
    long frames_written_ = 0;
    std::uint64_t bytes_written_ = 0;
    std::vector<std::thread> workers_;
};

}  // namespace polyroll::render
