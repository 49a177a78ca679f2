#include "shadelab/sphere.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <functional>
#include <limits>
#include <mutex>
#include <new>
#include <span>
#include <sstream>
#include <system_error>
#include <thread>

#include "shadelab/errors.h"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace shadelab {
namespace {

// DESIGN §1: the start tetrahedron and its counter-clockwise faces.
const double kSqrt2 = std::sqrt(2.0), kSqrt6 = std::sqrt(6.0);
const std::array<glm::dvec3, 4> kTetrahedron = {
    glm::dvec3{0, 0, 1},
    glm::dvec3{0, 2 * kSqrt2 / 3, -1.0 / 3},
    glm::dvec3{-kSqrt6 / 3, -kSqrt2 / 3, -1.0 / 3},
    glm::dvec3{kSqrt6 / 3, -kSqrt2 / 3, -1.0 / 3},
};
constexpr std::array<glm::uvec3, 4> kTetrahedronFaces = {glm::uvec3{3, 2, 1}, glm::uvec3{0, 1, 2},
                                                         glm::uvec3{0, 3, 1}, glm::uvec3{0, 2, 3}};

constexpr std::uint32_t kNoVertex = 0xffffffffu;

// Below this many items a second thread costs more than it saves.
constexpr std::size_t kParallelItems = 1 << 15;

#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
// The page has no threads (Emscripten without pthreads): every pass runs here.
class Helper {
public:
    template <typename Job> bool start(const Job&) { return false; }
    void wait() {}
};
#else
// A second thread kept for a builder's lifetime: each large pass hands it half the work instead of starting
// a thread per pass (a level-8 build has four such passes; clone3 took 0.15–0.25 ms under strace in the
// shadelab process, which has a GL driver loaded).
class Helper {
public:
    Helper() = default;
    Helper(const Helper&) = delete;
    Helper& operator=(const Helper&) = delete;
    ~Helper() {
        if (!thread_.joinable()) return;
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            quit_ = true;
        }
        wake_.notify_one();
        thread_.join();
    }
    // Runs job on the helper thread and returns at once; false (job not run) if no thread can be had.
    bool start(std::function<void()> job) {
        if (!thread_.joinable()) {
            try {
                thread_ = std::thread([this] { serve(); });
            } catch (const std::system_error&) { // a process limit: the caller does all of it
                return false;
            }
        }
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            job_ = std::move(job);
        }
        wake_.notify_one();
        return true;
    }
    // Returns once the job given to start has run.
    void wait() {
        std::unique_lock<std::mutex> lock(mutex_);
        done_.wait(lock, [this] { return !job_; });
    }

private:
    void serve() {
        std::unique_lock<std::mutex> lock(mutex_);
        for (;;) {
            wake_.wait(lock, [this] { return job_ || quit_; });
            if (quit_) return;
            lock.unlock();
            job_(); // job_ is only replaced after wait() has seen it cleared
            lock.lock();
            job_ = nullptr;
            done_.notify_one();
        }
    }
    std::thread thread_;
    std::mutex mutex_;
    std::condition_variable wake_, done_;
    std::function<void()> job_;
    bool quit_ = false;
};
#endif

// body(begin, end) over [0, n): for large n the helper takes the first half and this thread the second,
// else all of it here.
// Whether a second core is there to share with (glibc reads it from /sys on every call: asked once).
bool twoCores() {
    static const bool two = std::thread::hardware_concurrency() >= 2;
    return two;
}

template <typename Body> void inParallel(Helper& helper, std::size_t n, const Body& body) {
    if (n < kParallelItems || !twoCores() || !helper.start([&] { body(0, n / 2); })) {
        body(0, n);
        return;
    }
    struct WaitForHelper {
        Helper& helper;
        ~WaitForHelper() { helper.wait(); } // also if body throws: the helper's half refers to this frame
    } waitForHelper{helper};
    body(n / 2, n);
}

// The midpoint vertices of one split, numbered on first use: the k-th midpoint made is vertex first + k,
// its edge's end points are ends[k], and users[k] holds the two uses of its edge (3·triangle + the edge's
// place in it: 0 ab, 1 bc, 2 ac), the triangle that made it first. Every edge of a closed mesh has two
// uses, so each users[k] is filled. Positions are computed afterwards.
struct Midpoints {
    std::vector<std::uint32_t> ofEdge; // per edge of the level before: its midpoint vertex, or kNoVertex
    std::vector<glm::uvec2> ends;      // per midpoint (and one spare entry, see of())
    std::vector<glm::uvec2> users;     // per midpoint
    std::uint32_t first = 0;           // the vertex number of midpoint 0
    std::uint32_t count = 0;           // midpoints made so far

    void start(std::size_t edges, std::uint32_t firstVertex) {
        ofEdge.assign(edges, kNoVertex);
        ends.resize(edges + 1);
        users.resize(edges);
        first = firstVertex;
        count = 0;
    }

    // Without a branch on whether the edge is new (half the edges are, in no order a predictor learns):
    // the end points are written to the next free entry either way, and kept only when it is taken.
    void of(std::uint32_t number, std::uint32_t a, std::uint32_t b, std::uint32_t use) {
        const std::uint32_t seen = ofEdge[number];
        const std::uint32_t fresh = seen == kNoVertex ? 1 : 0;
        // k = fresh ? count : seen − first, as arithmetic (compilers turn the conditional into a branch).
        const std::uint32_t k = count + ((seen - first - count) & (fresh - 1));
        ends[count] = {a, b};
        users[k][int(1 - fresh)] = use;
        ofEdge[number] = first + k;
        count += fresh;
    }
};

// glm::normalize(v) is v · (1 / sqrt(v · v)). Its square root and division dominate a build (a level-8 build
// makes about 524,000 unit vectors) and take as long for 2, 4 or 8 doubles in one instruction as for one
// (measured here: 262,144 of them in 0.95 ms scalar, 0.44 with SSE2, 0.22 with AVX, 0.11 with AVX-512). Both
// are correctly rounded in every width, so the packed results are the scalar ones bit for bit; the products
// and sums around them stay in the scalar code, where no wider instruction set can fuse them.
using ReciprocalSqrts = void (*)(double* values, std::size_t n); // values[i] = 1 / sqrt(values[i])

void reciprocalSqrtsScalar(double* values, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) values[i] = 1.0 / std::sqrt(values[i]);
}

#if defined(__x86_64__) || defined(__i386__)
void reciprocalSqrtsSse2(double* values, std::size_t n) {
    std::size_t i = 0;
    for (; i + 2 <= n; i += 2)
        _mm_storeu_pd(values + i, _mm_div_pd(_mm_set1_pd(1.0), _mm_sqrt_pd(_mm_loadu_pd(values + i))));
    reciprocalSqrtsScalar(values + i, n - i);
}

__attribute__((target("avx"))) void reciprocalSqrtsAvx(double* values, std::size_t n) {
    std::size_t i = 0;
    for (; i + 4 <= n; i += 4)
        _mm256_storeu_pd(values + i,
                         _mm256_div_pd(_mm256_set1_pd(1.0), _mm256_sqrt_pd(_mm256_loadu_pd(values + i))));
    reciprocalSqrtsSse2(values + i, n - i);
}

__attribute__((target("avx512f"))) void reciprocalSqrtsAvx512(double* values, std::size_t n) {
    std::size_t i = 0;
    for (; i + 8 <= n; i += 8)
        _mm512_storeu_pd(values + i, _mm512_div_pd(_mm512_set1_pd(1.0),
                                                   _mm512_maskz_sqrt_pd(0xff, _mm512_loadu_pd(values + i))));
    reciprocalSqrtsAvx(values + i, n - i);
}

ReciprocalSqrts widestReciprocalSqrts() {
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx512f")) return reciprocalSqrtsAvx512;
    if (__builtin_cpu_supports("avx")) return reciprocalSqrtsAvx;
    return reciprocalSqrtsSse2;
}
#else
ReciprocalSqrts widestReciprocalSqrts() {
    return reciprocalSqrtsScalar;
}
#endif

const ReciprocalSqrts reciprocalSqrts = widestReciprocalSqrts();

// Copies a batch into an output array that is not read again in the build, bypassing the cache where the CPU
// can (x86's non-temporal stores): a plain store first reads the line it writes into, which for the
// megabytes of the last split's children and face normals doubles their memory traffic. Call finishStreams
// before another thread reads what was written.
void stream(void* to, const void* from, std::size_t bytes) {
#if defined(__x86_64__) || defined(__i386__)
    auto* out = static_cast<char*>(to);
    const auto* in = static_cast<const char*>(from);
    const std::size_t head = std::min(bytes, (16 - reinterpret_cast<std::uintptr_t>(out) % 16) % 16);
    std::memcpy(out, in, head);
    std::size_t at = head;
    for (; at + 16 <= bytes; at += 16)
        _mm_stream_si128(reinterpret_cast<__m128i*>(out + at),
                         _mm_loadu_si128(reinterpret_cast<const __m128i*>(in + at)));
    std::memcpy(out + at, in + at, bytes - at);
#else
    std::memcpy(to, from, bytes);
#endif
}
void finishStreams() {
#if defined(__x86_64__) || defined(__i386__)
    _mm_sfence();
#endif
}

// out[i] = glm::normalize(vector(i)) for i in [begin, end), bit for bit, the divisions packed: a batch of
// vectors and their squared lengths at a time (small enough to stay in L1).
template <typename Vector>
void normalizeEach(std::size_t begin, std::size_t end, glm::dvec3* out, const Vector& vector) {
    constexpr std::size_t kBatch = 256;
    glm::dvec3 v[kBatch];
    double scale[kBatch];
    for (std::size_t at = begin; at < end; at += kBatch) {
        const std::size_t n = std::min(kBatch, end - at);
        for (std::size_t i = 0; i < n; ++i) {
            v[i] = vector(at + i);
            scale[i] = glm::dot(v[i], v[i]);
        }
        reciprocalSqrts(scale, n);
        for (std::size_t i = 0; i < n; ++i) out[at + i] = v[i] * scale[i];
    }
}

// Bytes for a level, in double so that absurd levels (asked for by mistake) do not wrap around.
double memoryBytes(int level) {
    level = std::min(level, 1000); // 2·level must not overflow int; 4^1000 is inf in double, which is fine
    const double f = std::ldexp(4.0, 2 * level), v = std::ldexp(2.0, 2 * level) + 2;
    // The mesh, and the builder's second triangle array (the levels alternate between the two).
    const double cpu = v * 2 * sizeof(glm::dvec3) + f * (2 * sizeof(glm::uvec3) + sizeof(glm::dvec3));
    // The last split's edge numbers: three per triangle of the level before (F/4); per edge of its 3F/8,
    // the first end point, the midpoint, the midpoint's end points and its edge's two uses.
    const double edgeMap =
        (f / 4) * sizeof(glm::uvec3) + (3 * f / 8) * (2 * sizeof(std::uint32_t) + 2 * sizeof(glm::uvec2));
    const double gpuReady =
        std::max(v * sizeof(SmoothVertex) + f * 3 * sizeof(std::uint32_t), f * 3 * sizeof(FlatVertex));
    return cpu + edgeMap + gpuReady;
}

std::string humanBytes(double bytes) {
    static constexpr const char* kUnits[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB", "ZiB", "YiB"};
    int unit = 0;
    while (bytes >= 1024 && unit < 8) {
        bytes /= 1024;
        ++unit;
    }
    std::ostringstream out;
    out << std::fixed;
    out.precision(1);
    out << bytes << " " << kUnits[unit];
    return out.str();
}

} // namespace

std::size_t sphereVertexCount(int level) {
    return 2 * (std::size_t(1) << (2 * level)) + 2;
}
std::size_t sphereTriangleCount(int level) {
    return std::size_t(4) << (2 * level);
}

std::size_t sphereMemoryBytes(int level) {
    const double bytes = memoryBytes(level);
    return bytes < double(std::numeric_limits<std::size_t>::max()) ? std::size_t(bytes)
                                                                   : std::numeric_limits<std::size_t>::max();
}

void checkSubdivisionLevel(int level, std::string_view field) {
    if (level < 0) {
        throw InputError(std::string(field) + ": must be between 0 and " + std::to_string(kMaxSubdivisions) +
                         ", got " + std::to_string(level));
    }
    if (level > kMaxSubdivisions) {
        const std::string triangles =
            level <= 30 ? " (" + std::to_string(sphereTriangleCount(level)) + " triangles)" : "";
        // Beyond about level 40 the figure leaves every unit (and double, past level 500): give its power of
        // two, from the per-triangle cost at a level where it is exact.
        const std::string need =
            level <= 40
                ? humanBytes(memoryBytes(level))
                : "2^" + std::to_string(long(std::floor(2.0 * level + std::log2(memoryBytes(20)) - 40))) +
                      " bytes";
        throw InputError(std::string(field) + ": level " + std::to_string(level) + " would need about " +
                         need + triangles + "; the maximum supported level is " +
                         std::to_string(kMaxSubdivisions) + " (" + humanBytes(memoryBytes(kMaxSubdivisions)) +
                         ")");
    }
}

SphereMesh buildSphere(int level, VertexNormals normals) {
    SphereBuilder builder;
    builder.build(level, normals);
    return builder.take();
}

SphereBuilder::SphereBuilder() = default;
SphereBuilder::~SphereBuilder() = default;
SphereBuilder::SphereBuilder(SphereBuilder&&) noexcept = default;
SphereBuilder& SphereBuilder::operator=(SphereBuilder&&) noexcept = default;

const SphereMesh& SphereBuilder::build(int level, VertexNormals normals) {
    checkSubdivisionLevel(level);
    if (!scratch_) scratch_ = std::make_unique<Scratch>();
    try {
        buildInto(level, normals);
        return mesh_;
    } catch (const std::bad_alloc&) {
        throw RuntimeError("out of memory building the level-" + std::to_string(level) + " sphere (" +
                           std::to_string(sphereTriangleCount(level)) + " triangles), which needs about " +
                           humanBytes(memoryBytes(level)) +
                           "; free memory or raise the limit (ulimit -v), or use a lower --subdivisions");
    }
}

namespace {

// One level of the subdivision with its edges numbered, so that each edge's midpoint is found by its
// number instead of by a hash of its end points. Level n has F = 4ⁿ⁺¹ triangles and E = 6·4ⁿ edges; a
// triangle (a, b, c) lists its edges ab, bc, ac. Splitting numbers the edges of level n + 1 without a
// search: edge e's halves are 2e (the one at its first end point, `first[e]`) and 2e + 1, and triangle t's
// three inner edges (ab–ac, ab–bc, bc–ac) are 2E + 3t, 2E + 3t + 1 and 2E + 3t + 2.
struct EdgeLevel {
    std::vector<glm::uvec3> edges;    // per triangle: its edges ab, bc, ac
    std::vector<std::uint32_t> first; // per edge: the end point its half 2e starts from
};

void tetrahedronEdges(EdgeLevel& level) {
    level.edges.clear();
    level.first.clear();
    // (a, b) → edge number, for the six edges of the four start faces.
    std::vector<std::pair<glm::uvec2, std::uint32_t>> seen;
    auto edge = [&](std::uint32_t a, std::uint32_t b) {
        for (const auto& [ends, number] : seen)
            if ((ends.x == a && ends.y == b) || (ends.x == b && ends.y == a)) return number;
        seen.push_back({{a, b}, std::uint32_t(seen.size())});
        level.first.push_back(a);
        return seen.back().second;
    };
    for (const glm::uvec3& t : kTetrahedronFaces)
        level.edges.push_back({edge(t.x, t.y), edge(t.y, t.z), edge(t.x, t.z)});
}

// A vertex-normal sum the second part of the last split cannot add to in place: the first part adds to the
// same vertex, and its faces come first in triangle order.
struct LateAddition {
    std::uint32_t vertex, face;
};
struct LastSplit {
    std::vector<std::uint8_t> firstPartCorner; // per older vertex: 1 if a corner of a first-part parent
    std::vector<LateAddition> late;            // the second part's such additions, in its order
    bool marked = false;                       // firstPartCorner filled during the numbering
};

// Marks the corners of the first part's parents [0, firstPart) for splitLast's second part.
void markFirstPartCorners(LastSplit& split, const glm::uvec3* parents, std::size_t firstPart,
                          std::size_t older) {
    split.firstPartCorner.assign(older, 0);
    for (std::size_t i = 0; i < firstPart; ++i)
        for (int k = 0; k < 3; ++k) split.firstPartCorner[parents[i][k]] = 1;
    split.marked = true;
}

} // namespace

struct SphereBuilder::Scratch {
    EdgeLevel edges, nextEdges;
    std::vector<glm::uvec3> next; // the other triangle array; after the build, the last split's parents
    Midpoints midpoints;          // of the split being made; after the build, of the last split
    std::vector<glm::uvec2> pendingEnds; // the midpoint ends of the split before, its positions not yet made
    Helper helper;                       // the second thread of the large passes
    LastSplit lastSplit;                 // the second part's bookkeeping in the last split
};

namespace {

// The children of a split triangle (a, b, c) are (a,ab,ac), (ab,b,bc), (bc,c,ac), (ab,bc,ac): child k < 3
// holds corner k, and the midpoint of the edge in place s (ab, bc, ac) lies in these three children.
constexpr std::array<std::array<int, 3>, 3> kChildrenAtEdge = {{{0, 1, 3}, {1, 2, 3}, {0, 2, 3}}};

// Level 0's normals: no split, the tetrahedron's four faces.
void tetrahedronNormals(SphereMesh& mesh, VertexNormals kind) {
    const std::vector<glm::dvec3>& p = mesh.positions;
    mesh.faceNormals.resize(mesh.triangles.size());
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const glm::uvec3 t = mesh.triangles[i];
        mesh.faceNormals[i] = glm::normalize(glm::cross(p[t.y] - p[t.x], p[t.z] - p[t.x]));
    }
    if (kind == VertexNormals::Exact) {
        mesh.vertexNormals.assign(p.begin(), p.end()); // the unit sphere's normal
        return;
    }
    mesh.vertexNormals.assign(p.size(), glm::dvec3(0));
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
        for (int k = 0; k < 3; ++k) mesh.vertexNormals[mesh.triangles[i][k]] += mesh.faceNormals[i];
    for (glm::dvec3& n : mesh.vertexNormals) n = glm::normalize(n);
}

// The last split's children, their unit normals and (for averaged normals) each vertex's sum of them, in
// one pass over the parents: a child's normal is added to its vertices while it is still in L1, instead of
// a second pass reading all face normals back from memory, which cost more than computing them.
//
// DESIGN §1's averaged normal is the normalized sum of the unit normals of a vertex's faces, added in
// triangle order (as one pass over the triangles adds them). The last split fixes that order: a vertex older
// than the split is corner k of its parents and lies in child k of each, one face per parent in parent
// order; a midpoint lies in three children (kChildrenAtEdge) of each of the two parents sharing its edge,
// the first user's first. Each part walks its parents in order; the second part leaves the additions to
// vertices the first part also adds to for after both are done (`late`): the same additions in the same
// order, the same sums bit for bit.
void splitLast(Helper& helper, SphereMesh& mesh, std::span<const glm::uvec3> parents,
               const std::vector<glm::uvec3>& parentEdges, const Midpoints& made, VertexNormals kind,
               LastSplit& split) {
    const bool averaged = kind == VertexNormals::Averaged;
    const glm::dvec3* p = mesh.positions.data();
    glm::uvec3* children = mesh.triangles.data();
    mesh.faceNormals.resize(4 * parents.size());
    glm::dvec3* faceNormals = mesh.faceNormals.data();
    glm::dvec3* sums = nullptr;
    if (averaged) {
        mesh.vertexNormals.resize(mesh.positions.size());
        sums = mesh.vertexNormals.data();
        std::fill(sums, sums + made.first, glm::dvec3(0)); // the midpoints' sums start at their first user
    }
    split.late.clear();
    inParallel(helper, parents.size(), [&](std::size_t begin, std::size_t end) {
        const bool second = begin > 0; // the first part's parents are [0, begin)
        if (averaged && second && !split.marked)
            markFirstPartCorners(split, parents.data(), begin, made.first);
        auto addOlder = [&](std::uint32_t v, std::size_t face, const glm::dvec3& n) {
            if (second && split.firstPartCorner[v])
                split.late.push_back({v, std::uint32_t(face)});
            else
                sums[v] += n;
        };
        auto addMidpoint = [&](std::uint32_t m, std::size_t i, int place, const glm::dvec3* four) {
            const std::array<int, 3>& at = kChildrenAtEdge[place];
            const std::uint32_t firstUse = made.users[m - made.first].x;
            if (firstUse == 3 * i + std::size_t(place)) {
                sums[m] = glm::dvec3(0) + four[at[0]] + four[at[1]] + four[at[2]];
            } else if (second && firstUse < 3 * begin) {
                for (const int child : at)
                    split.late.push_back({m, std::uint32_t(4 * i + std::size_t(child))});
            } else {
                for (const int child : at) sums[m] += four[child];
            }
        };
        constexpr std::size_t kBatch = 64; // parents: 256 faces, their corners and unit normals in L1
        glm::dvec3 v[4 * kBatch];
        double scale[4 * kBatch];
        glm::uvec3 corners[kBatch], midpoints[kBatch], childBatch[4 * kBatch];
        for (std::size_t at = begin; at < end; at += kBatch) {
            const std::size_t n = std::min(kBatch, end - at);
            for (std::size_t j = 0; j < n; ++j) {
                const std::size_t i = at + j;
                const glm::uvec3 t = parents[i], e = parentEdges[i];
                const std::uint32_t ab = made.ofEdge[e.x], bc = made.ofEdge[e.y], ac = made.ofEdge[e.z];
                corners[j] = t;
                midpoints[j] = {ab, bc, ac};
                glm::uvec3* four = childBatch + 4 * j;
                four[0] = {t.x, ab, ac};
                four[1] = {ab, t.y, bc};
                four[2] = {bc, t.z, ac};
                four[3] = {ab, bc, ac};
                const glm::dvec3 a = p[t.x], b = p[t.y], c = p[t.z], pab = p[ab], pbc = p[bc], pac = p[ac];
                glm::dvec3* cross = v + 4 * j;
                cross[0] = glm::cross(pab - a, pac - a);
                cross[1] = glm::cross(b - pab, pbc - pab);
                cross[2] = glm::cross(c - pbc, pac - pbc);
                cross[3] = glm::cross(pbc - pab, pac - pab);
                for (int k = 0; k < 4; ++k) scale[4 * j + std::size_t(k)] = glm::dot(cross[k], cross[k]);
            }
            stream(children + 4 * at, childBatch, 4 * n * sizeof(glm::uvec3));
            reciprocalSqrts(scale, 4 * n);
            for (std::size_t f = 0; f < 4 * n; ++f) v[f] *= scale[f];
            stream(faceNormals + 4 * at, v, 4 * n * sizeof(glm::dvec3));
            if (!averaged) continue;
            for (std::size_t j = 0; j < n; ++j) {
                const std::size_t i = at + j, face = 4 * i;
                const glm::dvec3* four = v + 4 * j;
                addOlder(corners[j].x, face, four[0]);
                addOlder(corners[j].y, face + 1, four[1]);
                addOlder(corners[j].z, face + 2, four[2]);
                for (int place = 0; place < 3; ++place) addMidpoint(midpoints[j][place], i, place, four);
            }
        }
        finishStreams(); // before the join, after which the caller reads them
    });
    if (!averaged) {
        mesh.vertexNormals.assign(mesh.positions.begin(), mesh.positions.end()); // the unit sphere's normal
        return;
    }
    for (const LateAddition& late : split.late) sums[late.vertex] += faceNormals[late.face];
    inParallel(helper, mesh.vertexNormals.size(), [&](std::size_t begin, std::size_t end) {
        normalizeEach(begin, end, sums, [&](std::size_t i) { return sums[i]; });
    });
}

} // namespace

// Every array is sized once to the level's counts and written in place: kept from an earlier build of the
// same level, nothing is allocated or zero-filled again (std::vector's resize fills what it adds, which
// costs as much as writing the mesh). The triangles of successive levels alternate between the mesh's
// array and `next`, counted rather than resized.
void SphereBuilder::buildInto(int level, VertexNormals normals) {
    SphereMesh& mesh = mesh_;
    EdgeLevel& edges = scratch_->edges;
    EdgeLevel& nextEdges = scratch_->nextEdges;
    Midpoints& midpoints = scratch_->midpoints;
    mesh.level = level;
    mesh.positions.resize(sphereVertexCount(level));
    std::copy(kTetrahedron.begin(), kTetrahedron.end(), mesh.positions.begin());
    std::vector<glm::uvec3>* from = &mesh.triangles;
    std::vector<glm::uvec3>* to = &scratch_->next;
    from->resize(sphereTriangleCount(level));
    to->resize(sphereTriangleCount(level));
    std::copy(kTetrahedronFaces.begin(), kTetrahedronFaces.end(), from->begin());
    tetrahedronEdges(edges);
    std::size_t vertexCount = kTetrahedron.size(), triangleCount = kTetrahedronFaces.size();
    std::vector<glm::uvec2>& pendingEnds = scratch_->pendingEnds;
    std::uint32_t pendingFirst = 0;
    std::size_t pendingCount = 0;
    scratch_->lastSplit.marked = false;
    for (int n = 0; n < level; ++n) {
        const bool last = n + 1 == level; // the last split needs no edge numbers for a level after it
        const std::size_t edgeCount = edges.first.size();
        const glm::uvec3* parents = from->data();
        glm::uvec3* children = to->data();
        // Midpoints are numbered in the order the triangles first reach their edges (ab, bc, ac), which is
        // the order the seed's edge-midpoint map made them in: the same vertices, bit for bit, in the same
        // order.
        midpoints.start(edgeCount, std::uint32_t(vertexCount));
        if (!last) {
            nextEdges.edges.resize(4 * triangleCount);
            nextEdges.first.resize(2 * edgeCount + 3 * triangleCount);
        }
        // Numbering is sequential (first use decides); it only reads the parents and writes the midpoints.
        // Meanwhile the helper makes the positions of the split before, which numbering does not read,
        // and before the last split the marks splitLast's second part needs.
        const bool mark = last && normals == VertexNormals::Averaged && triangleCount >= kParallelItems;
        scratch_->lastSplit.marked = false;
        auto overlapped = [&] {
            normalizeEach(0, pendingCount, mesh.positions.data() + pendingFirst, [&](std::size_t k) {
                return (mesh.positions[pendingEnds[k].x] + mesh.positions[pendingEnds[k].y]) * 0.5;
            });
            if (mark) markFirstPartCorners(scratch_->lastSplit, parents, triangleCount / 2, vertexCount);
        };
        const bool helped = (pendingCount + (mark ? triangleCount : 0) >= kParallelItems / 4) && twoCores() &&
                            scratch_->helper.start(overlapped);
        struct WaitForHelper {
            Helper& helper;
            bool helped;
            ~WaitForHelper() {
                if (helped) helper.wait();
            }
        } waitForHelper{scratch_->helper, helped};
        for (std::size_t i = 0; i < triangleCount; ++i) {
            const glm::uvec3 t = parents[i], e = edges.edges[i];
            const auto use = std::uint32_t(3 * i);
            midpoints.of(e.x, t.x, t.y, use);
            midpoints.of(e.y, t.y, t.z, use + 1);
            midpoints.of(e.z, t.x, t.z, use + 2);
        }
        if (helped) {
            scratch_->helper.wait();
            waitForHelper.helped = false;
        } else {
            overlapped();
        }
        // Writing the children (and the next level's edge numbers) is per parent: both threads. The last
        // split's children are written by splitLast, with their normals.
        const std::uint32_t* midpointOf = midpoints.ofEdge.data();
        if (!last)
            inParallel(scratch_->helper, triangleCount, [&](std::size_t begin, std::size_t end) {
                for (std::size_t i = begin; i < end; ++i) {
                    const glm::uvec3 t = parents[i], e = edges.edges[i];
                    const std::uint32_t ab = midpointOf[e.x], bc = midpointOf[e.y], ac = midpointOf[e.z];
                    glm::uvec3* four = children + 4 * i;
                    four[0] = {t.x, ab, ac};
                    four[1] = {ab, t.y, bc};
                    four[2] = {bc, t.z, ac};
                    four[3] = {ab, bc, ac};
                    // The half of edge `number` that ends at vertex v, and the three inner edges.
                    auto half = [&](std::uint32_t number, std::uint32_t v) {
                        return 2 * number + (edges.first[number] == v ? 0 : 1);
                    };
                    const std::uint32_t inner = std::uint32_t(2 * edgeCount + 3 * i);
                    const std::uint32_t abac = inner, abbc = inner + 1, bcac = inner + 2;
                    glm::uvec3* childEdges = &nextEdges.edges[4 * i];
                    childEdges[0] = {half(e.x, t.x), abac, half(e.z, t.x)};
                    childEdges[1] = {half(e.x, t.y), half(e.y, t.y), abbc};
                    childEdges[2] = {half(e.y, t.z), half(e.z, t.z), bcac};
                    childEdges[3] = {abbc, bcac, abac};
                    nextEdges.first[abac] = ab;
                    nextEdges.first[abbc] = ab;
                    nextEdges.first[bcac] = bc;
                }
            });
        // normalize((a + b)/2) for every midpoint of the level; its end points are older vertices. Before a
        // further split, left to the helper during its numbering.
        if (last) {
            const std::uint32_t first = midpoints.first;
            const glm::uvec2* ends = midpoints.ends.data();
            glm::dvec3* positions = mesh.positions.data();
            inParallel(scratch_->helper, midpoints.count, [&](std::size_t begin, std::size_t end) {
                normalizeEach(begin, end, positions + first, [&](std::size_t k) {
                    return (positions[ends[k].x] + positions[ends[k].y]) * 0.5;
                });
            });
        } else {
            std::swap(midpoints.ends, pendingEnds);
            pendingFirst = midpoints.first;
            pendingCount = midpoints.count;
        }
        if (!last) {
            // Half 2e starts at edge e's first end point, half 2e + 1 at its midpoint.
            for (std::size_t number = 0; number < edgeCount; ++number) {
                nextEdges.first[2 * number] = edges.first[number];
                nextEdges.first[2 * number + 1] = midpoints.ofEdge[number];
            }
            std::swap(edges, nextEdges);
        }
        vertexCount += midpoints.count;
        triangleCount *= 4;
        std::swap(from, to); // `to` keeps the level before: the last split's parents
    }
    if (from != &mesh.triangles) std::swap(mesh.triangles, scratch_->next);
    if (level == 0)
        tetrahedronNormals(mesh, normals);
    else
        splitLast(scratch_->helper, mesh,
                  std::span<const glm::uvec3>(scratch_->next.data(), triangleCount / 4), edges.edges,
                  midpoints, normals, scratch_->lastSplit);
}

std::vector<SmoothVertex> smoothVertices(const SphereMesh& mesh) {
    std::vector<SmoothVertex> out(mesh.positions.size());
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = {glm::vec3(mesh.positions[i]), glm::vec3(mesh.vertexNormals[i])};
    return out;
}

std::vector<std::uint32_t> smoothIndices(const SphereMesh& mesh) {
    std::vector<std::uint32_t> out;
    out.reserve(mesh.triangles.size() * 3);
    for (const glm::uvec3& t : mesh.triangles) out.insert(out.end(), {t.x, t.y, t.z});
    return out;
}

std::vector<FlatVertex> flatVertices(const SphereMesh& mesh) {
    std::vector<FlatVertex> out;
    out.reserve(mesh.triangles.size() * 3);
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const glm::uvec3& t = mesh.triangles[i];
        const glm::dvec3 centroid = (mesh.positions[t.x] + mesh.positions[t.y] + mesh.positions[t.z]) / 3.0;
        for (int k = 0; k < 3; ++k)
            out.push_back(
                {glm::vec3(mesh.positions[t[k]]), glm::vec3(centroid), glm::vec3(mesh.faceNormals[i])});
    }
    return out;
}

double maxRadialDeviation(const SphereMesh& mesh) {
    // Vertices lie on the sphere, so the deepest point of a face is the foot of the perpendicular from the
    // origin when it falls inside the face; otherwise it lies on an edge, whose deepest point is its
    // midpoint (both ends are at radius 1).
    double minDistance = 1;
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const glm::uvec3& t = mesh.triangles[i];
        const glm::dvec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
        const glm::dvec3 n = mesh.faceNormals[i];
        const glm::dvec3 foot = glm::dot(a, n) * n;
        const bool inside = glm::dot(glm::cross(b - a, foot - a), n) >= 0 &&
                            glm::dot(glm::cross(c - b, foot - b), n) >= 0 &&
                            glm::dot(glm::cross(a - c, foot - c), n) >= 0;
        const double d = inside ? glm::length(foot)
                                : std::min({glm::length((a + b) * 0.5), glm::length((b + c) * 0.5),
                                            glm::length((c + a) * 0.5)});
        minDistance = std::min(minDistance, d);
    }
    return 1 - minDistance;
}

} // namespace shadelab
