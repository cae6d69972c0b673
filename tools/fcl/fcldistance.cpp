// FCL's distance query between two BVH models (OBBRSS, FCL's type for distance), timed on the
// files `gradle bench -Ponly=body-proximity` writes (build/bench/fcldist-*.txt: "nva nta nvb ntb",
// A's vertices and triangles, B's vertices and triangles in B's own frame, then B's pose as 12
// row-major values). Models prebuilt once; each call is FCL's traversal from the root pair with B
// placed by its pose (MeshDistanceTraversalNodeOBBRSS, what fcl::distance runs for two OBBRSS
// meshes). Built by tools/fcl/build; run by the bench, so both are measured in the same run.
//   fcldistance SAMPLE_MS SAMPLES WARMUP_MS FILE...
// prints one line per file: "fcldist FILE DISTANCE median_us=T" (T in this thread's CPU time: the
// machine is shared, and wall time counts other processes' turns)
#include <fcl/fcl.h>
#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <vector>
using namespace fcl;
typedef OBBRSS<double> BV;

static bool load(const char* f, std::vector<Vector3d>& va, std::vector<Triangle>& ta, std::vector<Vector3d>& vb,
                 std::vector<Triangle>& tb, Transform3d& pose) {
  FILE* fp = fopen(f, "r");
  if (!fp) return false;
  int nva, nta, nvb, ntb;
  if (fscanf(fp, "%d %d %d %d", &nva, &nta, &nvb, &ntb) != 4) return false;
  auto verts = [&](int n, std::vector<Vector3d>& v) {
    for (int i = 0; i < n; i++) { double x, y, z; if (fscanf(fp, "%lf %lf %lf", &x, &y, &z) != 3) return false; v.emplace_back(x, y, z); }
    return true;
  };
  auto tris = [&](int n, std::vector<Triangle>& t) {
    for (int i = 0; i < n; i++) { int a, b, c; if (fscanf(fp, "%d %d %d", &a, &b, &c) != 3) return false; t.emplace_back(a, b, c); }
    return true;
  };
  if (!verts(nva, va) || !tris(nta, ta) || !verts(nvb, vb) || !tris(ntb, tb)) return false;
  double m[12];
  for (int i = 0; i < 12; i++) if (fscanf(fp, "%lf", &m[i]) != 1) return false;
  pose.setIdentity();
  for (int r = 0; r < 3; r++) {
    for (int c = 0; c < 3; c++) pose.linear()(r, c) = m[4 * r + c];
    pose.translation()(r) = m[4 * r + 3];
  }
  fclose(fp);
  return true;
}

int main(int argc, char** argv) {
  if (argc < 5) { fprintf(stderr, "usage: fcldistance SAMPLE_MS SAMPLES WARMUP_MS FILE...\n"); return 2; }
  double sampleMs = atof(argv[1]), warmMs = atof(argv[3]);
  int samples = atoi(argv[2]);
  for (int f = 4; f < argc; f++) {
    std::vector<Vector3d> va, vb;
    std::vector<Triangle> ta, tb;
    Transform3d pose;
    if (!load(argv[f], va, ta, vb, tb, pose)) { fprintf(stderr, "fcldistance: cannot read %s\n", argv[f]); return 3; }
    BVHModel<BV> ma, mb;
    ma.beginModel(); ma.addSubModel(va, ta); ma.endModel();
    mb.beginModel(); mb.addSubModel(vb, tb); mb.endModel();
    DistanceRequestd req;
    DistanceResultd res;
    Transform3d I = Transform3d::Identity();
    auto once = [&]() {
      res.clear();
      detail::MeshDistanceTraversalNodeOBBRSS<double> node;
      detail::initialize(node, ma, I, mb, pose, req, res);
      detail::distance(&node);
      return res.min_distance;
    };
    double d = once(), sink = 0;
    auto cpuUs = []() { timespec ts; clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts); return ts.tv_sec * 1e6 + ts.tv_nsec / 1e3; };
    double t0 = cpuUs();
    long calls = 0;
    while (cpuUs() - t0 < warmMs * 1000 || calls < 2) { sink += once(); calls++; }
    double per = (cpuUs() - t0) / calls;
    long batch = std::max(1L, (long) (sampleMs * 1000 / per));
    std::vector<double> med;
    for (int s = 0; s < samples; s++) {
      double a = cpuUs();
      for (long i = 0; i < batch; i++) sink += once();
      med.push_back((cpuUs() - a) / batch);
    }
    std::sort(med.begin(), med.end());
    printf("fcldist %s %.17g median_us=%.3f sink=%d\n", argv[f], d, med[samples / 2], (int) sink % 7);
  }
  return 0;
}
