#pragma once
// TBB hands a parallel loop's tasks between threads, and back, through synchronisation inside
// libtbb, which Debian does not build with ThreadSanitizer: TSan would take every read of a task's
// body or range, and the caller's every read of what the tasks wrote, for a race. In the TSan
// build a body wrapped by handedOff() announces those hand-offs (a release after it is made or
// copied, an acquire before it is copied or run), and receiveHandOff() after the loop acquires
// what every task released; in other builds handedOff() is the body itself and receiveHandOff()
// nothing. The TSan check (scripts/check.sh tsan) then reports only races in what the tasks do.
// Such a loop takes tbb::simple_partitioner: the default partitioner's stealing flags are atomics
// inlined from TBB's headers into Strata's code, set on one thread and read on another through a
// hand-off TSan cannot see either.
#include <utility>

#if defined(__SANITIZE_THREAD__)
#include <sanitizer/tsan_interface.h>
#endif

namespace strata {

#if defined(__SANITIZE_THREAD__)
inline char* handOffToken() {
    static char token;
    return &token;
}
template <typename Body>
class HandedOffBody {
public:
    explicit HandedOffBody(Body body) : body_(std::move(body)) { __tsan_release(handOffToken()); }
    HandedOffBody(const HandedOffBody& other) : body_((__tsan_acquire(handOffToken()), other.body_)) {
        __tsan_release(handOffToken());
    }
    template <typename Range>
    void operator()(const Range& range) const {
        __tsan_acquire(handOffToken());
        body_(range);
        __tsan_release(handOffToken());
    }

private:
    Body body_;
};
template <typename Body>
HandedOffBody<Body> handedOff(Body body) {
    return HandedOffBody<Body>(std::move(body));
}
inline void receiveHandOff() { __tsan_acquire(handOffToken()); }
#else
template <typename Body>
Body handedOff(Body body) {
    return body;
}
inline void receiveHandOff() {}
#endif

}  // namespace strata
