#include "core/stats.h"

namespace pt {

WorkCounters& work_counters() {
  thread_local WorkCounters counters;
  return counters;
}

}  // namespace pt
