// A vote across the lanes of a GPU warp: whether any converged lane's
// predicate holds. OpenCL C 1.2 has no such builtin; NVIDIA's compiler takes
// PTX inline, where activemask and vote.sync give it (sm_70 and later). The
// speculative traversal (intersect.cl) uses it to decide when a warp's
// lanes test leaves together; the host sets ORB_WARP_VOTE for NVIDIA's
// OpenCL only (choose_traversal in librender/src/device_renderer.cpp).
//   ORB_WARP_VOTE=0  no vote (every other device): the ordered traversal.
//   ORB_WARP_VOTE=1  the PTX vote.
//   ORB_WARP_VOTE=2  for tests on CPUs: every lane answers "yes", so each
//                    lane speculates as far as it can; the same control flow
//                    as on the GPU, run lane by lane.
// (The default, 0, is kernel_features.h's.)

#if ORB_WARP_VOTE == 1
inline bool warp_any(bool p)
{
    int any;
    __asm__ volatile(
        "{\n\t.reg .pred p, q;\n\t.reg .b32 m;\n\tsetp.ne.s32 p, %1, 0;\n\tactivemask.b32 m;\n\t"
        "vote.sync.any.pred q, p, m;\n\tselp.s32 %0, 1, 0, q;\n\t}"
        : "=r"(any)
        : "r"((int)p));
    return any != 0;
}
#elif ORB_WARP_VOTE == 2
inline bool warp_any(bool p) { return true; }
#endif
