// Peak resident memory of a piece of work, for the memory benchmarks: Linux's
// high-water mark VmHWM, reset by writing 5 to /proc/self/clear_refs, less VmRSS before the work.
// Real pages touched, libraries and allocator slack included; malloc_trim first returns the free
// heap so that freed memory is not reused unseen.
#pragma once

#include <malloc.h>

#include <fstream>
#include <string>

namespace lexel::bench {

// A "VmRSS:"-style field of /proc/self/status in bytes; -1 when it cannot be read.
inline double ProcStatusBytes(const std::string& field) {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind(field + ":", 0) == 0)
            return 1024.0 * std::stod(line.substr(field.size() + 1));
    return -1.0;
}

// Bytes by which `work` raises the process's resident set at its peak; -1 when /proc cannot be
// used (then the benchmark reports no memory counter rather than a wrong one).
template <typename Work>
double PeakRssIncrease(Work&& work) {
    // Blocks over 1 MiB always mapped (glibc otherwise raises the threshold to the largest block
    // freed, and per-pixel arrays then reuse and fragment the heap): freed arrays leave the RSS.
    mallopt(M_MMAP_THRESHOLD, 1 << 20);
    malloc_trim(0);
    {
        std::ofstream clear("/proc/self/clear_refs");
        clear << "5";
        if (!clear) return -1.0;
    }
    const double before = ProcStatusBytes("VmRSS");
    work();
    const double peak = ProcStatusBytes("VmHWM");
    return before < 0 || peak < 0 ? -1.0 : peak - before;
}

}  // namespace lexel::bench
