#include "parallel/process.h"

#include <fstream>
#include <string>

namespace ffeti {

double peak_memory_mb() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmHWM:") {
      double kilobytes = 0;
      status >> kilobytes;
      return kilobytes / 1024.0;
    }
    status.ignore(4096, '\n');
  }
  return 0.0;
}

}  // namespace ffeti
