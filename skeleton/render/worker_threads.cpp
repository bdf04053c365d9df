#include "render/worker_threads.h"

#include <cstring>
#include <vector>

#include <pthread.h>

namespace pt {

namespace {

void* run(void* work) {
  (*static_cast<const std::function<void()>*>(work))();
  return nullptr;
}

}  // namespace

int run_on_threads(int count, size_t stack_bytes, const std::function<void()>& work, std::string* error) {
  pthread_attr_t attr;
  pthread_attr_init(&attr);
  int rc = pthread_attr_setstacksize(&attr, stack_bytes);
  std::vector<pthread_t> started;
  for (int i = 0; i < count && rc == 0; ++i) {
    pthread_t t;
    rc = pthread_create(&t, &attr, run, const_cast<std::function<void()>*>(&work));
    if (rc == 0) started.push_back(t);
  }
  pthread_attr_destroy(&attr);
  for (pthread_t t : started) pthread_join(t, nullptr);
  if (started.empty()) *error = std::string("cannot start a render thread: ") + std::strerror(rc);
  return int(started.size());
}

}  // namespace pt
