// Small double-precision vector types for the scene model (not firmware: the
// scene is ground truth, so it computes in double).
#pragma once

#include <cmath>

namespace scene {

struct vec2 {
    double x = 0.0;
    double y = 0.0;
};

struct vec3 {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;
};

inline vec3 operator+(vec3 a, vec3 b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline vec3 operator-(vec3 a, vec3 b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline vec3 operator-(vec3 a) {
    return {-a.x, -a.y, -a.z};
}
inline vec3 operator*(vec3 a, double s) {
    return {a.x * s, a.y * s, a.z * s};
}
inline vec3 operator*(double s, vec3 a) {
    return a * s;
}
inline double dot(vec3 a, vec3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline vec3 cross(vec3 a, vec3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(vec3 a) {
    return std::sqrt(dot(a, a));
}
// The unit vector along a; a must not be zero.
inline vec3 normalized(vec3 a) {
    return a * (1.0 / length(a));
}

// A 3x3 rotation, row-major: rotated = m * v.
struct mat3 {
    double m[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

    vec3 operator*(vec3 v) const {
        return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
                m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
                m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
    }
    // For a rotation the transpose is the inverse.
    vec3 transposed_times(vec3 v) const {
        return {m[0][0] * v.x + m[1][0] * v.y + m[2][0] * v.z,
                m[0][1] * v.x + m[1][1] * v.y + m[2][1] * v.z,
                m[0][2] * v.x + m[1][2] * v.y + m[2][2] * v.z};
    }
};

// Rotation by angle_rad about a unit axis (Rodrigues' formula).
inline mat3 rotation_about(vec3 axis, double angle_rad) {
    const double c = std::cos(angle_rad), s = std::sin(angle_rad), k = 1.0 - c;
    const vec3 a = axis;
    mat3 r;
    r.m[0][0] = c + a.x * a.x * k;
    r.m[0][1] = a.x * a.y * k - a.z * s;
    r.m[0][2] = a.x * a.z * k + a.y * s;
    r.m[1][0] = a.y * a.x * k + a.z * s;
    r.m[1][1] = c + a.y * a.y * k;
    r.m[1][2] = a.y * a.z * k - a.x * s;
    r.m[2][0] = a.z * a.x * k - a.y * s;
    r.m[2][1] = a.z * a.y * k + a.x * s;
    r.m[2][2] = c + a.z * a.z * k;
    return r;
}

}  // namespace scene
