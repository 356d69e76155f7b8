// Catmull-Clark, position-only re-evaluation and offset, timed on this machine on the cases the targets name,
// with OpenMesh's CatmullClarkT on the same input in the same run when it is installed.

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "nome/freed_memory.hpp"
#include "nome/ops/offset.hpp"
#include "nome/ops/pipeline.hpp"
#include "nome/ops/subdivide.hpp"
#include "support/memory_counter.hpp"
#include "support/new_process.hpp"
#include "support/shapes.hpp"

#ifdef NOME_HAVE_OPENMESH
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>
#endif
#ifdef NOME_HAVE_CGAL
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>
#endif

using namespace nome;

namespace {

// Best time of `runs` calls, in milliseconds: process CPU time (the machine is shared, and CPU time
// does not count the time other processes hold the cores) for single-threaded work, wall time for
// work on several threads.
enum class Clock { cpu, wall };

double now_ms(Clock clock) {
  timespec t{};
  clock_gettime(clock == Clock::cpu ? CLOCK_PROCESS_CPUTIME_ID : CLOCK_MONOTONIC, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

double best_ms(int runs, const std::function<void()>& work, Clock clock = Clock::cpu) {
  double best = 1e300;
  for (int i = 0; i < runs; ++i) {
    const double start = now_ms(clock);
    work();
    best = std::min(best, now_ms(clock) - start);
  }
  return best;
}

struct Refined {
  Refinement refinement;
  std::span<const Vec3> positions;
};

// A full refine: the topology pass and the position pass, the last level without adjacency, its
// positions in the refinement's own buffer.
Refined refine(const Mesh& base, int levels, int threads) {
  Refined r{Refinement(base, levels, BoundaryMode::edge_only, threads), {}};
  r.positions = r.refinement.refine_positions(base, SubdivisionRule::classic, threads);
  return r;
}

#ifdef NOME_HAVE_OPENMESH
struct DoubleTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using OmMesh = OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits>;

OmMesh to_openmesh(const Mesh& m) {
  OmMesh om;
  std::vector<OmMesh::VertexHandle> handles;
  for (const Vec3& p : m.positions()) handles.push_back(om.add_vertex(OmMesh::Point(p.x, p.y, p.z)));
  for (Index f = 0; f < m.num_faces(); ++f) {
    std::vector<OmMesh::VertexHandle> face;
    for (Index v : m.face_vertices(f)) face.push_back(handles[v]);
    om.add_face(face);
  }
  return om;
}
#endif

#ifdef NOME_HAVE_CGAL
using CgalMesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;

CgalMesh to_cgal(const Mesh& m) {
  CgalMesh cm;
  std::vector<CgalMesh::Vertex_index> handles;
  for (const Vec3& p : m.positions()) handles.push_back(cm.add_vertex({p.x, p.y, p.z}));
  for (Index f = 0; f < m.num_faces(); ++f) {
    std::vector<CgalMesh::Vertex_index> face;
    for (Index v : m.face_vertices(f)) face.push_back(handles[v]);
    cm.add_face(face);
  }
  return cm;
}
#endif

// A full refine into the blocks of the last one (Refinement::rebuild): what a caller that refines again
// (a slider that changes the topology, this bench's repeated runs) pays once its memory is warm.
std::span<const Vec3> refine_again(Refinement& refinement, const Mesh& base, int levels, int threads) {
  refinement.rebuild(base, levels, BoundaryMode::edge_only, threads);
  return refinement.refine_positions(base, SubdivisionRule::classic, threads);
}

// What the summary of targets needs from the level table.
struct LevelSix {
  double ms = 0, fresh_ms = 0, speed_up = 0, openmesh_ms = 0, cgal_ms = 0;
};

struct PeerMs {
  double openmesh = 0, cgal = 0;  // 0: not installed
};

// OpenMesh's and CGAL's times for the same subdivision, printed as multiples of ours (`ours_ms`).
PeerMs print_peers([[maybe_unused]] const Mesh& torus, [[maybe_unused]] int level,
                   [[maybe_unused]] double ours_ms) {
  PeerMs peers;
#ifdef NOME_HAVE_OPENMESH
  peers.openmesh = best_ms(level <= 4 ? 3 : 1, [&] {
    OmMesh om = to_openmesh(torus);
    OpenMesh::Subdivider::Uniform::CatmullClarkT<OmMesh> cc;
    cc.attach(om);
    cc(size_t(level));
    cc.detach();
  });
  std::printf(" %7.1fx", peers.openmesh / ours_ms);
#endif
#ifdef NOME_HAVE_CGAL
  peers.cgal = best_ms(level <= 4 ? 3 : 1, [&] {
    CgalMesh cm = to_cgal(torus);
    CGAL::Subdivision_method_3::CatmullClark_subdivision(cm, CGAL::parameters::number_of_iterations(level));
  });
  std::printf(" %8.1fx", peers.cgal / ours_ms);
#endif
  return peers;
}

void print_peer_legend() {
#ifdef NOME_HAVE_OPENMESH
  std::printf(
      "(OpenMesh column: OpenMesh CatmullClarkT time / ours single-threaded, same input, same run)\n");
#endif
#ifdef NOME_HAVE_CGAL
  std::printf(
      "(CGAL column: CGAL Surface_mesh CatmullClark_subdivision time / ours, same input, same run)\n");
#endif
}

// The level table: levels 1 to 6 of the torus, with the peers beside ours when `with_peers`.
LevelSix torus_levels(int threads_available, bool with_peers) {
  LevelSix six;
  const Mesh torus = build_mesh(test::torus(64, 32));
  std::printf(
      "64x32 quad torus, classic rule; full refine = topology pass + position pass, last level\n"
      "without edges/fans; best of several runs. ms (1 thr) is CPU time refining again into the blocks of\n"
      "the last refinement (Refinement::rebuild), fresh the same into new memory (a new Refinement; B/face\n"
      "its peak); ms (2 thr) is wall time, again into kept blocks; the speed-up is wall time on 1 thread /\n"
      "on 2 (it needs both cores free)\n\n");
  std::printf("%5s %10s %10s %10s %12s %9s %10s %12s %9s %9s\n", "level", "faces", "ms (1 thr)", "fresh",
              "Mfaces/s", "B/face", "ms (2 thr)", "speed-up", "OpenMesh", "CGAL");
  for (int level = 1; level <= 6; ++level) {
    const int runs = level <= 4 ? 10 : 8;
    double faces = 0;
    bench::reset_peak();
    const double fresh = best_ms(runs, [&] { faces = refine(torus, level, 1).refinement.num_faces(); });
    const double peak = double(bench::peak_bytes_since_reset());
    Refinement kept(torus, level);
    const double one = best_ms(runs, [&] { refine_again(kept, torus, level, 1); });
    // The speed-up compares wall times, one thread against two, in the same run.
    const double one_wall = best_ms(
        runs, [&] { refine_again(kept, torus, level, 1); }, Clock::wall);
    const double two = threads_available > 1
                           ? best_ms(
                                 runs, [&] { refine_again(kept, torus, level, 2); }, Clock::wall)
                           : one_wall;
    std::printf("%5d %10.0f %10.2f %10.2f %12.1f %9.1f %10.2f %11.2fx", level, faces, one, fresh,
                faces / one / 1e3, peak / faces, two, one_wall / two);
    const PeerMs peers = with_peers ? print_peers(torus, level, one) : PeerMs{};
    std::printf("\n");
    if (level == 6) six = {one, fresh, one_wall / two, peers.openmesh, peers.cgal};
  }
  if (with_peers) print_peer_legend();
  return six;
}

// The level-6 figure split into its two passes, each on 1 thread (CPU and wall time) and on 2 (wall): which
// of them keeps the 2-thread speed-up below its target.
void level_six_passes(int threads_available) {
  const Mesh torus = build_mesh(test::torus(64, 32));
  Refinement kept(torus, 6);
  kept.refine_positions(torus, SubdivisionRule::classic);
  const auto topology = [&](int threads) { kept.rebuild(torus, 6, BoundaryMode::edge_only, threads); };
  const auto positions = [&](int threads) {
    kept.refine_positions(torus, SubdivisionRule::classic, threads);
  };
  std::printf("\nlevel 6 by pass: %12s %12s %12s %9s\n", "ms (1 thr)", "wall (1 thr)", "wall (2 thr)",
              "speed-up");
  for (const auto& [name, pass] :
       {std::pair<const char*, std::function<void(int)>>{"topology", topology}, {"positions", positions}}) {
    const double cpu = best_ms(8, [&] { pass(1); });
    const double one = best_ms(
        8, [&] { pass(1); }, Clock::wall);
    const double two = threads_available > 1 ? best_ms(
                                                   8, [&] { pass(2); }, Clock::wall)
                                             : one;
    std::printf("%16s %12.2f %12.2f %12.2f %8.2fx\n", name, cpu, one, two, one / two);
  }
}

void mobius(int threads_available) {
  const Mesh band = build_mesh(test::mobius_band(256, 8));
  double faces = 0;
  const double one = best_ms(5, [&] { faces = refine(band, 4, 1).refinement.num_faces(); });
  const double two = threads_available > 1 ? best_ms(
                                                 5, [&] { refine(band, 4, 2); }, Clock::wall)
                                           : one;
  std::printf("\nMöbius band 256x8, level 4: %.0f faces, %.2f ms (%.1f Mfaces/s), 2 threads %.2f ms\n", faces,
              one, faces / one / 1e3, two);
}

void position_only(int threads_available) {
  const Mesh torus = build_mesh(test::torus(64, 32));
  Refined r = refine(torus, 4, 1);
  Mesh moved = torus;
  for (Vec3& p : moved.positions()) p *= 1.01;
  const double full = best_ms(10, [&] { refine(moved, 4, 1); });
  const double fast = best_ms(20, [&] { r.refinement.refine_positions(moved, SubdivisionRule::classic, 1); });
  const double fast2 =
      threads_available > 1
          ? best_ms(
                20, [&] { r.refinement.refine_positions(moved, SubdivisionRule::classic, 2); }, Clock::wall)
          : fast;
  std::printf(
      "\nlevel-4 torus (%u faces): full refine %.2f ms, position pass only %.2f ms (%.1fx faster);"
      " 2 threads %.2f ms wall\n",
      r.refinement.num_faces(), full, fast, full / fast, fast2);
  // The same through the pipeline, as a slider drives it: a new topology rebuilds the refinement and the
  // level-4 Mesh with its adjacency; moved vertices re-run only the position pass into the cached Mesh.
  PipelineSettings options;
  options.subdivision_levels = 4;
  const double rebuild = best_ms(5, [&] { Pipeline().run(moved, options); });
  Pipeline pipeline;
  pipeline.run(torus, options);
  bool at_torus = true;
  const double slide = best_ms(20, [&] {
    pipeline.run(at_torus ? moved : torus, options);
    at_torus = !at_torus;
  });
  std::printf("pipeline, level 4: rebuild %.2f ms, moved vertices %.2f ms (%.1fx faster)\n", rebuild, slide,
              rebuild / slide);
}

// The level-6 torus without and with creases (the ring of sharp edges around the tube at i = 0 and the
// ring along it at j = 0, which cross at a vertex of four creases): creases cost only where they are.
void creases() {
  const Mesh torus = build_mesh(test::torus(64, 32));
  Mesh creased = torus;
  Index sharp = 0;
  for (Index e = 0; e < creased.num_edges(); ++e) {
    const auto [a, b] = creased.edge(e).vertices;
    if ((a < 32 && b < 32) || (a % 32 == 0 && b % 32 == 0)) {
      creased.set_sharp(e, true);
      ++sharp;
    }
  }
  // The same rings semi-sharp (weight 2.5: creases for two levels, blended at the third) and their
  // crossing a corner of weight 3.
  Mesh weighted = torus;
  for (Index e = 0; e < weighted.num_edges(); ++e)
    if (creased.edge(e).is_sharp) weighted.set_edge_sharpness(e, 2.5f);
  weighted.set_vertex_sharpness(0, 3.0f);
  const double plain = best_ms(3, [&] { refine(torus, 6, 1); });
  const double with_creases = best_ms(3, [&] { refine(creased, 6, 1); });
  const double with_weights = best_ms(3, [&] { refine(weighted, 6, 1); });
  std::printf(
      "\nlevel-6 torus, full refine on 1 thread: %.1f ms without creases, %.1f ms with %u sharp edges,"
      " %.1f ms with them semi-sharp (2.5) and a corner (3)\n",
      plain, with_creases, sharp, with_weights);
}

struct FirstOffset {
  double first_ms = 0, warm_ms = 0;
};

// What a writer reads of the solid, without the file: every face's corners and their positions.
double read_through(const OffsetSurface& solid) {
  Vec3 sum(0.0);
  for (Index f = 0; f < solid.num_faces(); ++f)
    for (Index v : solid.face_vertices(f)) sum += solid.position(v);
  return sum.x + sum.y + sum.z;
}

// The level-5 torus's offset as `nome export` makes it: through the pipeline of a program that keeps
// freed memory (nome's main), the subdivision run first, then the offset streamed (run_surface: the
// normals and an OffsetSurface, read through once as a writer does). CPU milliseconds of the first time
// and the best of three after it.
FirstOffset export_offset_times() {
  PipelineSettings s;
  s.stage = Stage::offset;
  s.subdivision_levels = 5;
  s.offset_distance = 0.01;
  Pipeline pipeline;
  pipeline.set_input(build_mesh(test::torus(64, 32)));
  pipeline.run_before_surface(s);
  double checksum = 0.0;
  auto offset_ms = [&] {
    const double start = now_ms(Clock::cpu);
    checksum += read_through(*pipeline.run_surface(s).solid);
    return now_ms(Clock::cpu) - start;
  };
  const double first = offset_ms();
  const double warm = std::min({offset_ms(), offset_ms(), offset_ms()});
  return {checksum != 0.0 ? first : 0.0, warm};
}

// What `nome_bench_subdivide --first-offset [export]` runs and prints: the offset of the level-5 torus,
// normals included, in milliseconds, the first time in the process (after building its input, as a
// command line does) and the best of three after it, freed memory kept as the nome program keeps it; as a
// Mesh, or as `nome export` makes it (export_offset_times).
int print_first_offset(bool as_export) {
  keep_freed_memory();
  if (as_export) {
    const FirstOffset times = export_offset_times();
    std::printf("%f %f\n", times.first_ms, times.warm_ms);
    return 0;
  }
  const Mesh torus = build_mesh(test::torus(64, 32));
  Refined r = refine(torus, 5, 1);
  const Mesh level5 = r.refinement.mesh(torus, {r.positions.begin(), r.positions.end()});
  auto offset_ms = [&] {
    const double start = now_ms(Clock::cpu);
    offset(level5, {0.01});
    return now_ms(Clock::cpu) - start;
  };
  const double first = offset_ms();
  std::printf("%f %f\n", first, std::min({offset_ms(), offset_ms(), offset_ms()}));
  return 0;
}

// The same in a new process (output_of_new_process).
FirstOffset first_offset_in_new_process(bool as_export) {
  FirstOffset times;
  const std::string output =
      bench::output_of_new_process(std::string("--first-offset") + (as_export ? " export" : ""));
  if (std::sscanf(output.c_str(), "%lf %lf", &times.first_ms, &times.warm_ms) != 2) times = {};
  return times;
}

// The first offset's time over the warm one in a new process (first_offset_in_new_process): as a Mesh,
// and as `nome export` makes it.
struct FirstOffsetRatios {
  double mesh = 0, exported = 0;
};

FirstOffsetRatios offset_case() {
  const FirstOffset fresh = first_offset_in_new_process(false);
  const FirstOffset fresh_exported = first_offset_in_new_process(true);
  const Mesh torus = build_mesh(test::torus(64, 32));
  Refined r = refine(torus, 5, 1);
  const Mesh level5 = r.refinement.mesh(torus, {r.positions.begin(), r.positions.end()});
  double faces = 0;
  const double ms = best_ms(3, [&] { faces = offset(level5, {0.01}).num_faces(); });
  // As the viewer's pipeline rebuilds it: normals and solid into the blocks of the last ones.
  Normals normals;
  Mesh kept;
  const double rebuild_ms = best_ms(5, [&] {
    compute_normals(level5, normals);
    offset_into(level5, normals, 0.01, kept);
  });
  const double one_thread_wall_ms = best_ms(
      5,
      [&] {
        compute_normals(level5, normals);
        offset_into(level5, normals, 0.01, kept);
      },
      Clock::wall);
  const double two_threads_ms = best_ms(
      5,
      [&] {
        compute_normals(level5, normals);
        offset_into(level5, normals, 0.01, kept, 2);
      },
      Clock::wall);
  double checksum = 0.0;
  const double streamed_ms = best_ms(
      5, [&] { checksum += read_through(OffsetSurface(level5, compute_normals(level5).vertices, 0.01)); });
  Mesh solid = offset(level5, {0.01});
  const double normals_ms = best_ms(5, [&] { compute_normals(level5); });
  const double positions_ms = best_ms(5, [&] { offset_positions(level5, 0.011, solid.positions()); });
  std::printf(
      "\noffset of the level-5 torus (%u faces -> %.0f faces), normals included: %.1f ms as a Mesh with\n"
      "adjacency into the blocks of the last one (offset_into, the pipeline's rebuild), %.1f ms into fresh\n"
      "memory, %.1f ms streamed (an OffsetSurface read through once); normals alone %.1f ms; position pass\n"
      "only %.1f ms.\n"
      "Into the kept blocks on 2 threads: %.1f ms wall (%.2fx). In a new process: %.1f ms the first time,\n"
      "%.1f ms after it; as `nome export` makes it (the pipeline's subdivision first, the offset streamed)\n"
      "%.1f ms the first time, %.1f ms after it (CPU time, page faults included)\n",
      level5.num_faces(), faces, rebuild_ms, ms, checksum != 0.0 ? streamed_ms : 0.0, normals_ms,
      positions_ms, two_threads_ms, one_thread_wall_ms / two_threads_ms, fresh.first_ms, fresh.warm_ms,
      fresh_exported.first_ms, fresh_exported.warm_ms);
  return {fresh.first_ms / fresh.warm_ms, fresh_exported.first_ms / fresh_exported.warm_ms};
}

// The machine's load when the figures were taken: other processes on the two cores slow every figure
// (memory bandwidth is shared too), and a 2-thread speed-up needs both cores free.
std::string load_note() {
  FILE* f = std::fopen("/proc/loadavg", "r");
  double one_minute = -1.0;
  if (f) {
    if (std::fscanf(f, "%lf", &one_minute) != 1) one_minute = -1.0;
    std::fclose(f);
  }
  return one_minute < 0.0 ? std::string()
                          : "        (load average " + std::to_string(one_minute).substr(0, 4) +
                                " over the last minute: the figures need it below 1)\n";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--first-offset")
    return print_first_offset(argc > 2 && std::string(argv[2]) == "export");
  const int threads = 2;
  // --kernel: only our level table, without the peers and the other cases (for iterating on the kernel).
  if (argc > 1 && std::string(argv[1]) == "--kernel") {
    const LevelSix six = torus_levels(threads, false);
    level_six_passes(threads);
    std::printf(
        "\ngoal 4: level-6 torus %.1f ms CPU on 1 thread (target <= 65 ms), 2-thread speed-up %.2fx (target"
        " >= 1.8x)\n%s",
        six.ms, six.speed_up, load_note().c_str());
    return 0;
  }
  const LevelSix six = torus_levels(threads, true);
  level_six_passes(threads);
  mobius(threads);
  position_only(threads);
  creases();
  const FirstOffsetRatios first_offset = offset_case();
  // The figures beside their targets (the peers' times are from the table above).
  std::printf(
      "\ngoal 2: first offset in a process %.2fx the warm one as a Mesh, %.2fx as `nome export` makes it\n"
      "        (target <= 1.5x)\n"
      "goal 4: level-6 torus %.1f ms CPU on 1 thread, refined again into kept blocks (target <= 65 ms;\n"
      "        %.1f ms into fresh memory; OpenMesh %.0f ms, CGAL %.0f ms CPU on 1 thread, 0 = not "
      "installed),\n"
      "        2-thread speed-up %.2fx in wall time (target >= 1.8x)\n%s",
      first_offset.mesh, first_offset.exported, six.ms, six.fresh_ms, six.openmesh_ms, six.cgal_ms,
      six.speed_up, load_note().c_str());
  return 0;
}
