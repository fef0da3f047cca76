#pragma once

#include "lights/LightSample.h"
#include "math/Color.h"
#include "math/Vec2.h"
#include "math/Vec3.h"

namespace lancer {

struct Hit;

// A light source, sampled from a point being shaded.
class Light {
public:
    virtual ~Light() = default;

    // A sample of the light as seen from p; u in [0,1)^2 picks a point on lights with an extent.
    virtual LightSample sample(const Vec3& p, const Vec2& u) const = 0;

    // A delta light (a point or a direction) is one sample exactly: u is ignored.
    virtual bool isDelta() const = 0;

    // The solid-angle density with which sample(p, ·) picks the direction wi that reaches the
    // light's surface at `onLight` (for multiple importance sampling). 0 for delta lights.
    virtual float pdf(const Vec3& p, const Vec3& wi, const Hit& onLight) const;

    // The same for samples combined with BSDF sampling by multiple importance sampling, which
    // finds by itself the directions where the light is dim against its average: a light may
    // then leave them out and sample where it outshines that average (pbrt-v4's "incomplete
    // PDF", Karlik et al. 2019's MIS compensation). Its density may be 0 where the BSDF's is
    // not; any other use needs sample() and pdf(). By default, those.
    virtual LightSample sampleBesideBsdf(const Vec3& p, const Vec2& u) const {
        return sample(p, u);
    }
    virtual float pdfBesideBsdf(const Vec3& p, const Vec3& wi, const Hit& onLight) const {
        return pdf(p, wi, onLight);
    }

    // The total power (flux) the light emits, for choosing lights in proportion to it. Lights at
    // infinity need the radius of a sphere bounding the scene.
    virtual Color power(float sceneRadius) const = 0;

    // How many samples of the light the Whitted integrator averages per shading point (its soft
    // shadows); 1 for delta lights.
    int shadowSamples() const { return shadowSamples_; }
    void setShadowSamples(int count) { shadowSamples_ = count; }

private:
    int shadowSamples_ = 1;
};

}  // namespace lancer
