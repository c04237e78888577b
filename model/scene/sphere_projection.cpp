#include "model/scene/sphere_projection.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace scene {
namespace {

constexpr double pi = 3.14159265358979323846;

// Symmetric 2x2 [[a, b], [b, c]]: eigenvalues l1 >= l2 and unit eigenvectors.
struct sym2_eigen {
    double l1, l2;
    vec2 e1, e2;
};

sym2_eigen eigen_sym2(double a, double b, double c) {
    const double mean = 0.5 * (a + c);
    const double half_diff = 0.5 * (a - c);
    const double rad = std::sqrt(half_diff * half_diff + b * b);
    sym2_eigen out{mean + rad, mean - rad, {1.0, 0.0}, {0.0, 1.0}};
    if (rad > 0.0) {
        // Angle of e1: tan(2 theta) = 2b / (a - c).
        const double theta = 0.5 * std::atan2(b, half_diff);
        out.e1 = {std::cos(theta), std::sin(theta)};
        out.e2 = {-std::sin(theta), std::cos(theta)};
    }
    return out;
}

// Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_n).
template <int N>
struct gauss_legendre {
    std::array<double, N> x{}, w{};
    gauss_legendre() {
        for (int i = 0; i < N; ++i) {
            double z = std::cos(pi * (i + 0.75) / (N + 0.5));
            double dp = 1.0;
            for (int iter = 0; iter < 100; ++iter) {
                double p0 = 1.0, p1 = z;
                for (int k = 2; k <= N; ++k) {
                    const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
                    p0 = p1;
                    p1 = p2;
                }
                dp = N * (z * p1 - p0) / (z * z - 1.0);
                const double dz = p1 / dp;
                z -= dz;
                if (std::fabs(dz) < 1e-16) break;
            }
            x[i] = z;
            w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
        }
    }
};

struct ellipse_frame {
    double u0, v0;  // centre, normalized coordinates
    double q0;      // Q at the centre
    double a1, a2;  // semi-axes, normalized coordinates
    vec2 e1, e2;    // axis directions
    double det_a;   // det of -M2
};

// Z' > r must hold.
ellipse_frame ellipse_of(vec3 c, double r) {
    const double r2 = r * r;
    const double zz = c.z * c.z - r2;
    ellipse_frame e{};
    e.u0 = c.x * c.z / zz;
    e.v0 = c.y * c.z / zz;
    const double k = dot(c, c) - r2;
    const vec3 d{e.u0, e.v0, 1.0};
    const double dc = dot(d, c);
    e.q0 = dc * dc - dot(d, d) * k;
    const double a = c.y * c.y + c.z * c.z - r2;
    const double b = -c.x * c.y;
    const double cc = c.x * c.x + c.z * c.z - r2;
    e.det_a = a * cc - b * b;
    const sym2_eigen eig = eigen_sym2(a, b, cc);
    e.a1 = std::sqrt(e.q0 / eig.l1);
    e.a2 = std::sqrt(e.q0 / eig.l2);
    e.e1 = eig.e1;
    e.e2 = eig.e2;
    return e;
}

}  // namespace

bool intersect_sphere(vec3 origin, vec3 direction, vec3 centre, double radius, double* t) {
    const vec3 oc = centre - origin;
    const double a = dot(direction, direction);
    const double b = dot(direction, oc);
    const double c = dot(oc, oc) - radius * radius;
    const double disc = b * b - a * c;
    if (disc < 0.0) return false;
    const double root = std::sqrt(disc);
    double hit = (b - root) / a;
    if (hit <= 0.0) hit = (b + root) / a;  // origin inside the sphere
    if (hit <= 0.0) return false;
    *t = hit;
    return true;
}

sphere_image project_sphere(const pinhole_camera& camera, vec3 centre, double radius) {
    sphere_image out;
    const vec3 c = centre - camera.centre;
    if (!(c.z > radius)) return out;
    out.valid = true;
    const double f = camera.focal_px;
    const double r2 = radius * radius;
    const double zz = c.z * c.z - r2;
    out.ellipse_centre = {camera.cx + f * c.x * c.z / zz, camera.cy + f * c.y * c.z / zz};
    out.point_centre = camera.project(centre);
    const double half_u = radius * std::sqrt(c.x * c.x + c.z * c.z - r2) / zz;
    const double half_v = radius * std::sqrt(c.y * c.y + c.z * c.z - r2) / zz;
    out.min_x = out.ellipse_centre.x - f * half_u;
    out.max_x = out.ellipse_centre.x + f * half_u;
    out.min_y = out.ellipse_centre.y - f * half_v;
    out.max_y = out.ellipse_centre.y + f * half_v;
    const ellipse_frame e = ellipse_of(c, radius);
    out.area_px = f * f * pi * e.q0 / std::sqrt(e.det_a);

    // Pixel i covers [i - 0.5, i + 0.5): the first touched is floor(min + 0.5).
    const int x0 = std::max(0, static_cast<int>(std::floor(out.min_x + 0.5)));
    const int y0 = std::max(0, static_cast<int>(std::floor(out.min_y + 0.5)));
    const int x1 = std::min(camera.width - 1, static_cast<int>(std::floor(out.max_x + 0.5)));
    const int y1 = std::min(camera.height - 1, static_cast<int>(std::floor(out.max_y + 0.5)));
    if (x1 >= x0 && y1 >= y0) out.pixel_box = dsp::box{x0, y0, x1 - x0 + 1, y1 - y0 + 1};
    out.inside_image = out.min_x >= -0.5 && out.min_y >= -0.5 && out.max_x <= camera.width - 0.5 &&
                       out.max_y <= camera.height - 0.5;
    return out;
}

double visible_mean_depth(const pinhole_camera& camera, vec3 centre, double radius) {
    const vec3 c = centre - camera.centre;
    if (!(c.z > radius)) return 0.0;
    const ellipse_frame e = ellipse_of(c, radius);
    const double sqrt_q0 = std::sqrt(e.q0);

    constexpr int psi_nodes = 32;
    constexpr int phi_nodes = 64;
    static const gauss_legendre<psi_nodes> gl;
    // Integral of t(rho, phi) rho d rho d phi over the unit disc, rho = sin(psi),
    // divided by the disc's area pi.
    double sum = 0.0;
    for (int j = 0; j < phi_nodes; ++j) {
        const double phi = 2.0 * pi * j / phi_nodes;
        const double cp = std::cos(phi), sp = std::sin(phi);
        const double wx = e.a1 * cp * e.e1.x + e.a2 * sp * e.e2.x;
        const double wy = e.a1 * cp * e.e1.y + e.a2 * sp * e.e2.y;
        for (int i = 0; i < psi_nodes; ++i) {
            const double psi = 0.25 * pi * (gl.x[i] + 1.0);  // [-1, 1] -> [0, pi/2]
            const double s = std::sin(psi), co = std::cos(psi);
            const vec3 d{e.u0 + s * wx, e.v0 + s * wy, 1.0};
            // Q = q0 (1 - rho^2) exactly, so sqrt(Q) = sqrt(q0) cos(psi).
            const double t = (dot(d, c) - sqrt_q0 * co) / dot(d, d);
            sum += gl.w[i] * t * s * co;
        }
    }
    const double mean_t = sum * (0.25 * pi) * (2.0 * pi / phi_nodes) / pi;
    return camera.centre.z + mean_t;  // d has unit Z, so the hit's depth is t
}

}  // namespace scene
