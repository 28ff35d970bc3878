#include "bench/bench_race.h"

#include <algorithm>

#include "bench/bench_process.h"
#include "progress.h"

namespace strata {

double Entrant::medianWall() const { return median(wall); }
double Entrant::medianCpu() const { return median(cpu); }

std::optional<std::string> race(std::vector<Entrant>& entrants, int repeats,
                                const std::filesystem::path& log, const std::string& label) {
    const size_t count = entrants.size();
    ProgressReporter progress(label, count * static_cast<uint64_t>(repeats), "run");
    uint64_t runs = 0;
    for (int round = 0; round < repeats; ++round) {
        for (size_t k = 0; k < count; ++k) {
            Entrant& entrant = entrants[(static_cast<size_t>(round) + k) % count];
            const ProcessTiming t = runTimed(entrant.argv, log);
            if (!t.ok() || (entrant.readLog && !entrant.readLog(log))) return entrant.name;
            entrant.wall.push_back(t.wall);
            entrant.cpu.push_back(t.cpu);
            progress.update(++runs, 0);
        }
    }
    progress.finish(runs, 0);
    return std::nullopt;
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

}  // namespace strata
