// Facts about this process for reports.
#pragma once

namespace ffeti {

/// Peak resident memory of this process in MiB (VmHWM of /proc/self/status; 0 if unknown).
double peak_memory_mb();

}  // namespace ffeti
