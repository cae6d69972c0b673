// FCL's 24-DOP BVH search, timed on the meshes `gradle bench -Ponly=collision-fcl` writes
// (build/bench/fcl-*.txt: "nv nt", A's vertices, B's vertices already placed in A's frame by the
// pose, the triangles). Trees prebuilt in one frame, the search alone (fcl::collide would
// deep-copy both models on every call). Built by tools/fcl/build; run by the bench itself, so
// FCL and HandSim are measured in the same run on the same machine.
//   fclbench SAMPLE_MS SAMPLES WARMUP_MS FILE...
// prints one line per file: "fcl FILE TRIANGLES PAIRS median_us=T"
#include <fcl/fcl.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>
using namespace fcl;
typedef KDOP<double, 24> BV;

static bool load(const char* f, std::vector<Vector3d>& va, std::vector<Vector3d>& vb, std::vector<Triangle>& t) {
  FILE* fp = fopen(f, "r");
  if (!fp) return false;
  int nv, nt;
  if (fscanf(fp, "%d %d", &nv, &nt) != 2) return false;
  for (int s = 0; s < 2; s++)
    for (int i = 0; i < nv; i++) {
      double x, y, z;
      if (fscanf(fp, "%lf %lf %lf", &x, &y, &z) != 3) return false;
      (s == 0 ? va : vb).emplace_back(x, y, z);
    }
  for (int i = 0; i < nt; i++) {
    int a, b, c;
    if (fscanf(fp, "%d %d %d", &a, &b, &c) != 3) return false;
    t.emplace_back(a, b, c);
  }
  fclose(fp);
  return true;
}

int main(int argc, char** argv) {
  if (argc < 5) { fprintf(stderr, "usage: fclbench SAMPLE_MS SAMPLES WARMUP_MS FILE...\n"); return 2; }
  double sampleMs = atof(argv[1]), warmMs = atof(argv[3]);
  int samples = atoi(argv[2]);
  for (int f = 4; f < argc; f++) {
    std::vector<Vector3d> va, vb;
    std::vector<Triangle> t;
    if (!load(argv[f], va, vb, t)) { fprintf(stderr, "fclbench: cannot read %s\n", argv[f]); return 3; }
    auto ma = std::make_shared<BVHModel<BV>>(), mb = std::make_shared<BVHModel<BV>>();
    ma->beginModel(); ma->addSubModel(va, t); ma->endModel();
    mb->beginModel(); mb->addSubModel(vb, t); mb->endModel();
    CollisionRequestd req(1000000, false);
    Transform3d I = Transform3d::Identity();
    CollisionResultd res;
    auto once = [&]() {
      res.clear();
      detail::MeshCollisionTraversalNode<BV> node;
      detail::initialize(node, *ma, I, *mb, I, req, res);
      detail::collide(&node);
      return res.numContacts();
    };
    size_t pairs = once(), sink = 0;
    using clk = std::chrono::steady_clock;
    auto t0 = clk::now();
    long calls = 0;
    while (std::chrono::duration<double, std::milli>(clk::now() - t0).count() < warmMs || calls < 2) { sink += once(); calls++; }
    double per = std::chrono::duration<double, std::micro>(clk::now() - t0).count() / calls;
    long batch = std::max(1L, (long) (sampleMs * 1000 / per));
    std::vector<double> med;
    for (int s = 0; s < samples; s++) {
      auto a = clk::now();
      for (long i = 0; i < batch; i++) sink += once();
      med.push_back(std::chrono::duration<double, std::micro>(clk::now() - a).count() / batch);
    }
    std::sort(med.begin(), med.end());
    printf("fcl %s %zu %zu median_us=%.2f sink=%zu\n", argv[f], t.size(), pairs, med[samples / 2], sink % 7);
  }
  return 0;
}
