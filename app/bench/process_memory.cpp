#include "bench/process_memory.h"

#include <fstream>
#include <string>
#include <nlohmann/json.hpp>

#include "bench/bench_process.h"

namespace strata {

long peakResidentKiB() {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);) {
        // "VmHWM:\t  123456 kB"
        if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
    }
    return 0;
}

long reportedPeakResidentKiB(const std::filesystem::path& log) {
    const nlohmann::json report = lastJsonReport(log);
    if (!report.is_object() || !report.contains("peak_rss_mib")) return -1;
    return static_cast<long>(report["peak_rss_mib"].get<double>() * 1024.0 + 0.5);
}

}  // namespace strata
