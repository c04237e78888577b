// The scene renderer, which is most of a rendered test's time (a box case
// spends about nine tenths of it here, not in the firmware): one camera's
// frame of a spinning textured ball by its width in pixels, and the ball
// texture's cosine against the C library's, side by side in one program.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "model/scene/ball_paths.h"
#include "model/scene/cosine.h"
#include "model/scene/renderer.h"
#include "model/scene/sequence.h"

namespace {

// The arguments a texture sums: wave numbers up to 9 a radius, phases to 2 pi.
std::vector<double> texture_arguments() {
    std::vector<double> x(4096);
    for (size_t i = 0; i < x.size(); ++i) x[i] = -9.0 + 24.0 * static_cast<double>(i) / x.size();
    return x;
}

double libm_cos(double x) {
    return std::cos(x);
}

// The cosines of the texture's arguments summed by `cosine`: the C
// library's (BM_cos<libm_cos>) or the renderer's (BM_cos<scene::cosine>).
template <double (*cosine)(double)>
void BM_cos(benchmark::State& state) {
    const std::vector<double> x = texture_arguments();
    for (auto _ : state) {
        double sum = 0.0;
        for (double v : x) sum += cosine(v);
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(x.size()));
}
BENCHMARK_TEMPLATE(BM_cos, libm_cos);
BENCHMARK_TEMPLATE(BM_cos, scene::cosine);

// A ball state.range(0) px wide at 2.5 m, spinning 5 rev/s, over the
// procedural background, rendered by the right camera mid-flight.
void BM_render_ball(benchmark::State& state) {
    scene::scenario s = scene::default_scenario(3);
    const double depth_m = 2.5;
    s.scene.balls.front().radius_m = 0.5 * state.range(0) * depth_m / s.scene.rig.focal_px();
    s.scene.balls.front().spin_rad_s = 5 * 2 * M_PI;
    s.scene.balls.front().path = scene::line_path(depth_m, 1.0, 0.0);
    const scene::renderer renderer(s.scene);
    scene::rgb_image out;
    for (auto _ : state) {
        renderer.render(scene::camera_id::right, 0.1, &out, nullptr);
        benchmark::DoNotOptimize(out.pixels.data());
    }
}
BENCHMARK(BM_render_ball)->Arg(40)->Arg(120)->Arg(240)->Unit(benchmark::kMillisecond);

}  // namespace
BENCHMARK_MAIN();
