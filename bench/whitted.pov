// bench/whitted.pov: scenes/whitted.json written for POV-Ray 3.7, for the comparison benchmark
// (bench/povray_comparison.sh, results in docs/BENCHMARKS.md).
//
// Render with (the script does this):
//   povray +Ibench/whitted.pov +O/tmp/whitted-povray.png +W640 +H480 \
//          +AM1 +A0.0 +R4 +J1.0 File_Gamma=sRGB -D -P +WT2
//
// How each part of the lancer scene maps onto POV-Ray:
//
// * Handedness. lancer is right-handed, POV-Ray left-handed. Every z coordinate is negated
//   (x, y, z) -> (x, y, -z): camera, look_at, sphere centres, triangle vertices and lights. A
//   mirror turns a right-handed frame into a left-handed one, so the picture is not flipped:
//   +x is still "right" on screen and +y "up".
//
// * Camera. lancer: vfov 40 degrees, vertical. POV-Ray's `angle` is the horizontal field of
//   view: angle = 2 atan(tan(20 deg) * 640/480) = 51.8 degrees with right = 4/3 x, up = y gives
//   exactly 40 degrees vertically. Both aim a pixel's centre ray at the same point (checked: a
//   half-pixel shift of the POV-Ray camera makes the two images differ more, not less).
//
// * Recursion depth. lancer max_depth 5 = the camera ray plus 5 reflection/refraction bounces,
//   i.e. at most 6 surface hits along a path. POV-Ray's max_trace_level N allows N surface hits
//   (the camera ray is level 1; checked with two facing mirrors: N = 1 shows only the first
//   mirror, no reflection). So max_trace_level = 6.
//
// * adc_bailout. POV-Ray by default stops a ray whose accumulated weight is below 1/255
//   (adaptive depth control); lancer does the same with `--adc-bailout 0.00392156863` (its
//   default, as the scene file's, is 0: every ray with a non-zero weight, down to max_depth).
//   The headline benchmark runs both at 1/255, POV-Ray's default; `Declare=ADC=0` on the command
//   line turns it off here, for the comparison of both renderers tracing every ray.
//
// * Shading. lancer's Whitted equation is
//     L = ka*ambient + sum_l V_l E_l (kd max(0, n.L) + ks max(0, n.h)^shininess [n.L > 0])
//         + kr L_reflected + kt L_refracted
//   and POV-Ray 3.7's classic finish is the same sum:
//     ambient:  pigment * finish.ambient * global ambient_light   -> pigment = kd, ambient 1,
//               ambient_light = the scene's "ambient" (lancer's ka defaults to kd)
//     diffuse:  finish.diffuse * pigment * light * n.L (brilliance 1) -> diffuse 1
//     specular: finish.specular * light * (n.h)^(1/roughness), h the normalized half vector of
//               the eye and light directions: Blinn-Phong, not multiplied by the pigment
//               -> specular ks, roughness 1/shininess
//     reflection: finish.reflection * L_reflected -> reflection kr
//   Both skip a light when n.L <= 0 and shade the side of the surface the ray arrived on.
//
// * Lights. lancer's point light gives E = I / d^2. POV-Ray 3.7's fade gives
//   colour * 2 / (1 + (d / fade_distance)^fade_power). With fade_power 2 and a small
//   fade_distance f this is colour * 2 f^2 / (f^2 + d^2), so colour = I / (2 f^2) matches
//   I / d^2 to a relative error of f^2 / d^2: with f = 0.01 and d > 3 here, below 2e-5.
//   (POV-Ray 3.7 has no exact inverse-square option: fade_distance 0 disables fading.)
//
// * Glass (lancer: kd 0, ks 1, shininess 300, kt 0.95, ior 1.5, kr 0). lancer splits the weights
//   with the exact unpolarised dielectric Fresnel term F: reflected kt*F, refracted kt*(1 - F);
//   shadow rays are multiplied by kt = 0.95 at every glass surface they cross (no refraction of
//   shadow rays, no caustics). POV-Ray: pigment transmit 0.95 (shadow rays are multiplied by
//   0.95 at each surface crossed: identical), interior ior 1.5, reflection {0, 0.95 fresnel on}
//   (POV-Ray's fresnel is the same unpolarised formula, so reflected = 0.95 F exactly) and
//   conserve_energy, which scales the refracted ray by (1 - reflected): refracted =
//   0.95 (1 - 0.95 F) instead of lancer's 0.95 (1 - F). The difference is 0.0475 F: 0.002 at
//   normal incidence (F = 0.04), more only near the silhouette. POV-Ray's "transmit" also dims
//   the pigment's ambient and diffuse by (1 - 0.95), but both are 0 for this glass, as in lancer.
//   (Total internal reflection cannot happen inside a single sphere, so the two renderers'
//   different TIR handling does not matter here.)
//
// * Checker. lancer: `even` where floor(x) + floor(z) is even (a plane's uv are world (x, z)).
//   POV-Ray's checker: first colour where floor(x) + floor(y) + floor(z) is even, y = 0 on the
//   floor. With z negated floor(-z) = -floor(z) - 1, which flips the parity, so the colours are
//   listed odd first. The squares' edges land on the same lines (x and z integers) in both.
//
// * Antialiasing. lancer: 16 stratified, jittered samples over every pixel, box-averaged.
//   POV-Ray: +AM1 (non-adaptive supersampling) +A0.0 (threshold 0: every pixel is supersampled)
//   +R4 (a 4 x 4 grid) +J1.0 (each sample jittered within its grid cell): 16 stratified jittered
//   samples per pixel, the same pattern as lancer's. POV-Ray's method 1 also keeps the first
//   ray it traced at the pixel centre and averages it in (17 camera rays per pixel), and traces
//   the row above and the column left of each 32 x 32 block once more to decide whether to
//   antialias: 17.06 camera rays per pixel in all, 1.066x lancer's 16. No setting gives
//   exactly 16: +AM2 with +R3 traces 22 rays per pixel (a 5 x 5 corner grid), +R2 about 6.
//
// * Not the same: lancer renders in single precision with a pbrt-style error-bounded offset for
//   spawned rays; POV-Ray works in double precision with fixed epsilons. lancer's image is
//   written as sRGB (File_Gamma=sRGB on the POV-Ray side), both clamp to [0, 1].

#version 3.7;

#ifndef (ADC) #declare ADC = 1/255; #end   // POV-Ray's default adaptive depth control

global_settings {
  assumed_gamma 1.0                         // linear colours, as lancer's
  max_trace_level 6                         // = lancer max_depth 5 (see above)
  adc_bailout ADC
  ambient_light rgb <0.08, 0.08, 0.1>       // the scene's "ambient"
}

camera {
  perspective
  location <0, 1.6, -7>
  right x * image_width / image_height
  up y
  // POV-Ray's angle is horizontal: 2 atan(tan(40 / 2) * 4/3) = 51.8 degrees = lancer's vfov 40.
  angle 2 * degrees(atan(tan(radians(40 / 2)) * image_width / image_height))
  look_at <0, 0.9, 0>
}

background { rgb <0.35, 0.5, 0.8> }

// Point lights: colour = I / (2 f^2), f = fade_distance (see above).
#declare FadeDistance = 0.01;
#declare Scale = 1 / (2 * FadeDistance * FadeDistance);
light_source { <-4, 7, -5> color rgb <60, 60, 60> * Scale
               fade_distance FadeDistance fade_power 2 }
light_source { <5, 4, -3> color rgb <25, 22, 18> * Scale
               fade_distance FadeDistance fade_power 2 }

// floor: checker kd, ks 0.1, shininess 16, kr 0.1
plane {
  y, 0
  texture {
    pigment {
      checker color rgb <0.7, 0.12, 0.1>, color rgb <0.9, 0.9, 0.85>   // odd first: z is negated
    }
    finish { ambient 1 diffuse 1 specular 0.1 roughness 1 / 16 reflection 0.1 }
  }
}

// mirror: kd 0.02, ks 0.8, shininess 500, kr 0.9
sphere {
  <-1.6, 1.0, 1.2>, 1.0
  texture {
    pigment { color rgb 0.02 }
    finish { ambient 1 diffuse 1 specular 0.8 roughness 1 / 500 reflection 0.9 }
  }
}

// glass: kd 0, ks 1, shininess 300, kt 0.95, ior 1.5
sphere {
  <0.4, 0.8, -1.2>, 0.8
  texture {
    pigment { color rgbt <1, 1, 1, 0.95> }
    finish {
      ambient 0 diffuse 0 specular 1 roughness 1 / 300
      reflection { 0, 0.95 fresnel on }
      conserve_energy
    }
  }
  interior { ior 1.5 }
}

// shiny: kd (0.1, 0.35, 0.8), ks 0.6, shininess 80
sphere {
  <2.0, 0.7, 0.4>, 0.7
  texture {
    pigment { color rgb <0.1, 0.35, 0.8> }
    finish { ambient 1 diffuse 1 specular 0.6 roughness 1 / 80 }
  }
}

// gold triangle: kd (0.8, 0.6, 0.15), ks 0.3, shininess 40
triangle {
  <-0.4, 0, 3.2>, <1.8, 0, 3.2>, <0.7, 2.2, 3.6>
  texture {
    pigment { color rgb <0.8, 0.6, 0.15> }
    finish { ambient 1 diffuse 1 specular 0.3 roughness 1 / 40 }
  }
}
