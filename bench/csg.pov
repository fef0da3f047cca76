// bench/csg.pov: scenes/csg-whitted.json written for POV-Ray 3.7, for the comparison benchmark
// (bench/povray_comparison.sh --scene csg, results in docs/BENCHMARKS.md). The conventions are
// those of bench/whitted.pov, whose header explains them in full; this one says how they apply
// here and what is new (the solids, CSG, the transforms).
//
// Render with (the script does this):
//   povray +Ibench/csg.pov +O/tmp/csg-povray.png +W640 +H400 \
//          +AM1 +A0.0 +R4 +J1.0 File_Gamma=sRGB -D -P +WT2
//
// * Handedness. Every z coordinate is negated, (x, y, z) -> (x, y, -z): camera, look_at,
//   lights, the wall plane, the children's centres, ends and corners, and the translations.
//
// * Transforms. lancer applies scale, then rotate [ax, ay, az, degrees] (counter-clockwise
//   about the axis, looking down it from its tip: the right-hand rule), then translate; a
//   child's transform first, then its csg's. In the mirrored world the transform M T M (M the
//   mirror z -> -z) is applied to the mirrored object. Conjugating a rotation by a mirror keeps
//   the angle and mirrors the axis and flips the sense: M R(a, t) M = R(M a, -t). POV-Ray's
//   `rotate y*t` is the matrix of R(y, t) (the right-hand-rule matrix, which in POV-Ray's
//   left-handed frame is its left-hand rule), so lancer's rotate [0, 1, 0, t] becomes
//   `rotate y*(-t)` and [1, 0, 0, t] becomes `rotate x*(-t)`; translate [x, y, z] becomes
//   `translate <x, y, -z>`, after the rotation, as in lancer. (No scale in this scene.)
//
// * Camera. lancer: vfov 40 degrees vertically at 640x400. POV-Ray's `angle` is horizontal:
//   angle = 2 atan(tan(20 deg) * 640/400) = 60.4 degrees with right = 1.6 x, up = y.
//
// * Recursion depth. lancer max_depth 8 = the camera ray plus 8 bounces, 9 surface hits along a
//   path; POV-Ray counts the camera ray as level 1: max_trace_level 9.
//
// * adc_bailout. POV-Ray's default 1/255 as the headline, with lancer's `--adc-bailout` at the
//   same value, and `Declare=ADC=0` on the command line (lancer: `--adc-bailout 0`, its default)
//   for every ray down to max_depth, as in whitted.pov.
//
// * Shading. As in whitted.pov: pigment = kd, finish { ambient 1 diffuse 1 specular ks
//   roughness 1/shininess reflection kr }, ambient_light = the scene's "ambient" (lancer's ka
//   defaults to kd, as here everywhere). Materials without "specular" have ks = 0 in lancer:
//   POV-Ray's specular 0 (its default). lancer's default shininess 32 is then irrelevant.
//
// * Lights. Point lights with E = I / d^2: colour I / (2 f^2), fade_distance f = 0.01,
//   fade_power 2 (POV-Ray's 2 / (1 + (d/f)^2) is then I / d^2 to a relative error f^2 / d^2,
//   1.1e-5 at most here: no surface is nearer than 3 units to either light).
//
// * Checker floor (even 0.7, odd 0.45, scale 1, on the plane's uv = world (x, z)). POV-Ray's
//   checker gives its first colour where floor(x) + floor(y) + floor(z) is even, y = 0 on the
//   floor; negating z flips the parity, so the colours are listed odd first (as whitted.pov).
//   The wall (lancer z = -3, normal +z) is `plane { z, 3 }` here; planes are two-sided in both.
//
// * Glass (lancer: diffuse 0, transmission 0.95, ior 1.5; no "specular": ks = 0, no highlight).
//   As in whitted.pov: pigment transmit 0.95, interior ior 1.5, reflection { 0, 0.95 fresnel on }
//   and conserve_energy, ambient 0 (lancer's ka = kd = 0), diffuse 0, specular 0. Reflected:
//   0.95 F in both; refracted: 0.95 (1 - 0.95 F) here, 0.95 (1 - F) in lancer; shadow rays lose
//   5% at every surface of the result they cross, in both. The texture and interior are given
//   to the csg; POV-Ray hands both to the children that have none, as lancer does its material.
//   Total internal reflection does happen here (inside the lens and the three-sphere union),
//   unlike in the Whitted scene: lancer weighs the internally reflected ray kr + kt F = 0.95
//   (F = 1); POV-Ray 3.7 (Trace::ComputeLightedTexture) skips its ordinary reflection and adds
//   the internally reflected ray unfiltered, with weight 1: 5% more per internal bounce.
//
// * CSG. lancer's csg is POV-Ray's: union, intersection and difference of solids, each
//   surface piece keeping its child's material, a child without one taking the csg's. POV-Ray
//   does the same with textures: a texture given to a csg goes to the children without one; the
//   carved surface of a subtracted child keeps that child's texture (the gold bore of the red
//   block, the black pips of the die, the green bite of the blue sphere). One difference of
//   vocabulary: POV-Ray's `union` keeps the children's surfaces inside one another, and its
//   `merge` removes them. lancer's union has no inner surfaces ("a union of glass spheres has no
//   surfaces inside"), so the glass union is a `merge` here; the opaque pawn stays a `union`
//   (its inner surfaces can never be seen or shadow anything: every ray stops at the outer one).
//
// * Solids. box { min, max }; sphere { centre, radius }; cylinder { base, top, radius } and
//   cone { base, base radius, top, top radius }, closed by caps in both (no `open`); a lancer
//   torus about the y axis at centre c is POV-Ray's torus { R, r translate c } (POV-Ray's torus
//   lies about the y axis through the origin).
//
// * Antialiasing. +AM1 +A0.0 +R4 +J1.0: 16 stratified jittered samples on every pixel plus
//   POV-Ray's centre ray (about 17.06 camera rays per pixel), lancer 16 (see whitted.pov).

#version 3.7;

#ifndef (ADC) #declare ADC = 1/255; #end   // POV-Ray's default adaptive depth control

global_settings {
  assumed_gamma 1.0                         // linear colours, as lancer's
  max_trace_level 9                         // = lancer max_depth 8 (see above)
  adc_bailout ADC
  ambient_light rgb <0.08, 0.08, 0.08>      // the scene's "ambient"
}

camera {
  perspective
  location <0, 2.4, -7.5>
  right x * image_width / image_height
  up y
  // POV-Ray's angle is horizontal: 2 atan(tan(40 / 2) * 1.6) = 60.4 degrees = lancer's vfov 40.
  angle 2 * degrees(atan(tan(radians(40 / 2)) * image_width / image_height))
  look_at <0, 0.9, 0>
}

background { rgb <0.02, 0.02, 0.03> }

// Point lights: colour = I / (2 f^2), f = fade_distance (see above).
#declare FadeDistance = 0.01;
#declare Scale = 1 / (2 * FadeDistance * FadeDistance);
light_source { <2.5, 5.5, -5> color rgb <55, 52, 48> * Scale
               fade_distance FadeDistance fade_power 2 }
light_source { <-4, 3, -3> color rgb <12, 12, 14> * Scale
               fade_distance FadeDistance fade_power 2 }

// The materials of csg-whitted.json.
#declare T_Wall = texture {
  pigment { color rgb <0.55, 0.55, 0.6> }
  finish { ambient 1 diffuse 1 specular 0 }
}
#declare T_Glass = texture {
  pigment { color rgbt <1, 1, 1, 0.95> }
  finish {
    ambient 0 diffuse 0 specular 0
    reflection { 0, 0.95 fresnel on }
    conserve_energy
  }
}
#declare I_Glass = interior { ior 1.5 }
#declare T_Ivory = texture {
  pigment { color rgb <0.85, 0.82, 0.75> }
  finish { ambient 1 diffuse 1 specular 0.3 roughness 1 / 80 }
}
#declare T_Pip = texture {
  pigment { color rgb <0.05, 0.05, 0.08> }
  finish { ambient 1 diffuse 1 specular 0 }
}
#declare T_Red = texture {
  pigment { color rgb <0.75, 0.15, 0.1> }
  finish { ambient 1 diffuse 1 specular 0.3 roughness 1 / 40 }
}
#declare T_Green = texture {
  pigment { color rgb <0.2, 0.6, 0.25> }
  finish { ambient 1 diffuse 1 specular 0 }
}
#declare T_Blue = texture {
  pigment { color rgb <0.15, 0.3, 0.75> }
  finish { ambient 1 diffuse 1 specular 0.3 roughness 1 / 40 }
}
#declare T_Gold = texture {
  pigment { color rgb <0.55, 0.4, 0.1> }
  finish { ambient 1 diffuse 1 specular 0 reflection 0.4 }
}

// floor: checker even 0.7, odd 0.45 (odd first: z is negated)
plane {
  y, 0
  texture {
    pigment { checker color rgb 0.45, color rgb 0.7 }
    finish { ambient 1 diffuse 1 specular 0 }
  }
}

// wall: lancer's plane through (0, 0, -3), normal +z
plane { z, 3 texture { T_Wall } }

// glass lens: the intersection of two spheres, its axis (z) turned upright by rotate [1,0,0,90]
intersection {
  sphere { <0, 0, 0.55>, 0.8 }
  sphere { <0, 0, -0.55>, 0.8 }
  texture { T_Glass }
  interior { I_Glass }
  rotate x * -90
  translate <-2.4, 0.75, -0.9>
}

// red block drilled through by a gold cylinder (the bore is gold)
difference {
  box { <-0.6, 0, -0.6>, <0.6, 1.2, 0.6> }
  cylinder { <0, 0.6, 1>, <0, 0.6, -1>, 0.32 texture { T_Gold } }
  texture { T_Red }
  rotate y * 25
  translate <-0.9, 0, 0.9>
}

// die: (box intersected with a sphere) minus six black pips
difference {
  intersection {
    box { <-0.5, -0.5, -0.5>, <0.5, 0.5, 0.5> }
    sphere { <0, 0, 0>, 0.68 }
  }
  sphere { <0, 0.56, 0>, 0.1 texture { T_Pip } }
  sphere { <0.56, 0.22, -0.22>, 0.1 texture { T_Pip } }
  sphere { <0.56, -0.22, 0.22>, 0.1 texture { T_Pip } }
  sphere { <-0.22, 0.22, -0.56>, 0.1 texture { T_Pip } }
  sphere { <0, 0, -0.56>, 0.1 texture { T_Pip } }
  sphere { <0.22, -0.22, -0.56>, 0.1 texture { T_Pip } }
  texture { T_Ivory }
  rotate y * -35
  translate <0.55, 0.5, -0.7>
}

// bitten sphere: blue minus green (the bite is green); the csg has no material of its own
difference {
  sphere { <1.9, 0.8, 0.8>, 0.8 texture { T_Blue } }
  sphere { <1.45, 1.15, 0.15>, 0.5 texture { T_Green } }
}

// pawn: a union of a cylinder, two tori, a cone and a sphere
union {
  cylinder { <0, 0, 0>, <0, 0.12, 0>, 0.45 }
  torus { 0.36, 0.09 translate y * 0.14 }
  cone { <0, 0.12, 0>, 0.34, <0, 0.8, 0>, 0.11 }
  torus { 0.17, 0.05 translate y * 0.8 }
  sphere { <0, 1.03, 0>, 0.21 }
  texture { T_Ivory }
  scale 1.4
  translate <-2.2, 0, 1.4>
}

// three glass spheres: lancer's union has no inner surfaces, which is POV-Ray's merge
merge {
  sphere { <2.2, 0.45, -1.2>, 0.45 }
  sphere { <2.75, 0.45, -1.0>, 0.45 }
  sphere { <2.45, 0.95, -1.1>, 0.42 }
  texture { T_Glass }
  interior { I_Glass }
}
