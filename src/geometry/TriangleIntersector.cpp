#include "geometry/TriangleIntersector.h"

namespace lancer {

void TriangleIntersector::recomputeInDouble(int lanes, const Float4 (&x)[3], const Float4 (&y)[3],
                                            Float4 (&e)[3]) {
    float xs[3][4], ys[3][4], es[3][4];
    for (int i = 0; i < 3; ++i) {
        x[i].store(xs[i]);
        y[i].store(ys[i]);
        e[i].store(es[i]);
    }
    for (int lane = 0; lane < 4; ++lane) {
        if (!(lanes >> lane & 1)) continue;
        for (int i = 0; i < 3; ++i) {
            if (es[i][lane] != 0) continue;
            // Edge i runs from vertex i + 1 to vertex i + 2.
            const int a = (i + 1) % 3, b = (i + 2) % 3;
            es[i][lane] = static_cast<float>(double(xs[a][lane]) * double(ys[b][lane]) -
                                             double(ys[a][lane]) * double(xs[b][lane]));
        }
    }
    alignas(16) float row[4];
    for (int i = 0; i < 3; ++i) {
        for (int lane = 0; lane < 4; ++lane)
            row[lane] = es[i][lane];
        e[i] = Float4::load(row);
    }
}

}  // namespace lancer
