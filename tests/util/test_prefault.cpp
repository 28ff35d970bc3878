// prefault: the pages it backs take no fault when first written, the elements resizePrefaulted
// makes are value-initialised, and a range without a whole page is left alone.
#include <doctest/doctest.h>

#include <cstdint>
#include <vector>
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#include "util/prefault.h"

using namespace strata;

namespace {

long threadMinorFaults() {
    rusage usage{};
    getrusage(RUSAGE_THREAD, &usage);
    return usage.ru_minflt;
}

constexpr long kPages = 4096;

// The minor faults taken by writing one byte in each of kPages pages of a fresh mapping (no huge
// pages, so that every page would fault on its own), prefaulted first or not.
long faultsWritingFreshPages(bool prefaulted, bool& populated) {
    const auto pageSize = static_cast<size_t>(sysconf(_SC_PAGESIZE));
    const size_t length = kPages * pageSize;
    void* mapped = mmap(nullptr, length, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    REQUIRE(mapped != MAP_FAILED);
    madvise(mapped, length, MADV_NOHUGEPAGE);
    auto* bytes = static_cast<volatile unsigned char*>(mapped);
    if (prefaulted) populated = prefault(mapped, length);
    const long before = threadMinorFaults();
    for (size_t i = 0; i < length; i += pageSize) bytes[i] = 1;
    const long faults = threadMinorFaults() - before;
    munmap(mapped, length);
    return faults;
}

}  // namespace

TEST_CASE("prefault: prefaulted pages are written without a fault each, where the kernel can populate") {
    bool populated = false;
    const long unprefaulted = faultsWritingFreshPages(false, populated);
    const long prefaulted = faultsWritingFreshPages(true, populated);
    // The control: without prefault every page faults (the count is the measurement's own check).
    CHECK(unprefaulted >= 4000);
    if (!populated) {
        MESSAGE("this kernel has no MADV_POPULATE_WRITE (Linux 5.14): the pages fault in as before");
        return;
    }
    CHECK(prefaulted < 40);
}

TEST_CASE("prefault: a range holding no whole page is left to fault in, and resizePrefaulted value-initialises") {
    alignas(4096) static unsigned char page[2 * 4096];
    CHECK_FALSE(prefault(page + 1, 4096));  // spans two pages, holds neither whole
    CHECK_FALSE(prefault(page, 0));

    std::vector<double> values;
    resizePrefaulted(values, 1 << 20);
    REQUIRE(values.size() == size_t{1} << 20);
    bool allZero = true;
    for (double v : values) allZero = allZero && v == 0.0;
    CHECK(allZero);
    std::vector<int> none;
    resizePrefaulted(none, 0);
    CHECK(none.empty());
}
