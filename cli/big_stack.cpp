#include "cli/big_stack.hpp"

#include <pthread.h>

#include <exception>

#include "base/heap_pages.hpp"

namespace lumen::cli {
namespace {

struct Job {
    const std::function<void()>* work;
    std::exception_ptr error;
};

void* thread_main(void* arg) {
    Job* job = static_cast<Job*>(arg);
    back_thread_heap_with_huge_pages();
    try {
        (*job->work)();
    } catch (...) {
        job->error = std::current_exception();
    }
    return nullptr;
}

}  // namespace

void run_with_big_stack(const std::function<void()>& work, std::size_t stack_bytes) {
    Job job{&work, nullptr};
    pthread_attr_t attr;
    pthread_t thread;
    bool started = false;
    if (pthread_attr_init(&attr) == 0) {
        started = pthread_attr_setstacksize(&attr, stack_bytes) == 0 &&
                  pthread_create(&thread, &attr, thread_main, &job) == 0;
        pthread_attr_destroy(&attr);
    }
    if (!started) {
        work();  // no big stack available: still run, with the limits the interpreter enforces
        return;
    }
    pthread_join(thread, nullptr);
    if (job.error) std::rethrow_exception(job.error);
}

}  // namespace lumen::cli
