// bench/cornell-radiosity.pov: the Mitsuba Cornell box (tests/cli/data/cornell/cornell.json)
// written for POV-Ray 3.7, lit by its radiosity alone, for issue 12's curve of error against
// time (bench/radiosity_time_to_error.py, results in docs/BENCHMARKS.md).
//
// Render with (the script does this, at several quality levels):
//   povray +Ibench/cornell-radiosity.pov +O/tmp/cornell-povray.exr +FE +W256 +H256 \
//          +AM1 +A0.0 +R3 -J -D -P +WT2 Declare=COUNT=200 Declare=NEAREST=10 ...
//
// Every radiosity setting below is declared with #ifndef, so that `Declare=NAME=VALUE` on the
// command line sets it (POV-Ray's own default in brackets where it differs):
//   COUNT (35)           sample rays per radiosity sample, 1 to 1600
//   NEAREST (5)          nearest_count: samples averaged at a point, 1 to 20
//   ERROR_BOUND (1.8)    error_bound: the larger, the more a sample is reused
//   RECURSION (2)        recursion_limit: bounces of light, 1 to 20 (1: the lamp's direct light
//                        alone). The reference holds every bounce, so 12 by default here: the
//                        cut at 7 bounces takes 2% of this box's light
//                        (tests/cli/data/cornell/SOURCES.md), after 12 about 0.2% is left
//   PRETRACE_START (0.08), PRETRACE_END (0.04): the pretrace passes' block sizes, as fractions of
//                        the image's width (0.01 = 2.6 pixels here)
//   LOW_ERROR (0.5)      low_error_factor: error_bound during the pretrace is scaled by this
//   MIN_REUSE (0.015)    minimum_reuse: the nearest a sample is reused, as a fraction of the
//                        image's width
//   RAD_ADC (0.01)       the radiosity rays' adc_bailout (weight below which a ray is not traced)
// always_sample off, normal on, media off, brightness 1, gray_threshold 0, max_sample -1 (none).
//
// How each part of the lancer scene maps onto POV-Ray:
//
// * Handedness. lancer is right-handed, POV-Ray left-handed. Every z coordinate is negated
//   (x, y, z) -> (x, y, -z): camera and triangle vertices. As in bench/whitted.pov the picture is
//   not mirrored: +x is "right" on screen and +y "up" in both.
//
// * Camera. lancer: at (0, 0, 3.9) looking at the origin, vfov 39.3077 degrees vertical, 256 x 256.
//   POV-Ray's `angle` is the horizontal field of view: 2 atan(tan(39.3077 / 2) * 256 / 256) =
//   39.3077 degrees, with right = x and up = y (a square image). Both aim a pixel's centre ray at
//   the same point. Checked: the lamp covers rows 32-40, columns 106-149 in both images, and a
//   shift of POV-Ray's image by one pixel in any direction raises its RMSE against the reference
//   by 29% or more.
//
// * Pixels. The reference averages 16384 samples over each pixel (a box filter). POV-Ray: +AM1
//   +A0.0 +R3 -J (as the script renders): every pixel is supersampled on a 3 x 3 grid (plus the
//   pixel's centre ray), not jittered, so that edges are averaged over the pixel as in the
//   reference and the image has no noise of its own from the antialiasing.
//
// * Light. The scene has no light_source: the lamp is an emitting surface, and everything else is
//   lit by POV-Ray's radiosity alone (ambient_light 0, every finish's ambient 0), as the reference
//   is lit by its area emitter alone. POV-Ray's radiosity gathers, at each sample point, the
//   cosine-weighted mean of the radiance its `count` rays find (the lamp's emission among it) and
//   a surface's colour is pigment * diffuse * that mean, that is rho E / pi: Lambert's
//   reflection rho / pi with diffuse 1 and pigment = the albedo. (Checked by the image's level:
//   with RECURSION=1 the image's mean is 0.97 of lancer `path` with max_depth 1, with
//   RECURSION=2 0.98 of max_depth 2; docs/BENCHMARKS.md.)
//
// * The lamp (lancer: diffuse [0.885809, 0.698859, 0.666422], emission [18.387, 13.9873,
//   6.75357]). POV-Ray 3.7 multiplies a finish's `emission` by the pigment, so pigment = the
//   albedo (which it also reflects with diffuse 1, as Mitsuba's lamp has the white BSDF) and
//   emission = radiance / albedo per channel = [20.757296, 20.014481, 10.134074]: the lamp seen
//   from below shows the radiance [18.387, 13.9873, 6.75357] (plus what it reflects). Mitsuba's
//   area emitter and its diffuse BSDF are one-sided (the lamp's normal points down); POV-Ray's
//   emission is two-sided, so the lamp's upper side is black through `interior_texture` (a
//   triangle's "inside" is the side its normal points away from; with cornell.json's vertex
//   order and z negated, that is the upper side: the camera, below, sees the lamp's emission).
//   Without it, the 1 cm gap between the lamp and the ceiling glows and leaks light (the image
//   is about 4% brighter).
//
// * Outputs. assumed_gamma 1.0 and OpenEXR (+FE), which POV-Ray writes linear, unclamped: a
//   pixel's value is radiance, as in the reference.
//
// * Not the same: POV-Ray's radiosity has no exact direct lighting from emitters: the lamp's
//   light, as every other, reaches a sample point only through the `count` hemisphere rays that
//   hit it (the lamp covers a small solid angle, so its direct light is sampled noisily) and is
//   interpolated between the cached samples (error_bound, nearest_count), which blurs shadows and
//   contact darkening. Bounces stop at recursion_limit and wherever a ray's weight falls below
//   RAD_ADC. The reference's paths end only by Russian roulette (unbiased).

#version 3.7;

#ifndef (COUNT) #declare COUNT = 200; #end
#ifndef (NEAREST) #declare NEAREST = 10; #end
#ifndef (ERROR_BOUND) #declare ERROR_BOUND = 0.5; #end
#ifndef (RECURSION) #declare RECURSION = 12; #end
#ifndef (PRETRACE_START) #declare PRETRACE_START = 0.08; #end
#ifndef (PRETRACE_END) #declare PRETRACE_END = 0.01; #end
#ifndef (LOW_ERROR) #declare LOW_ERROR = 0.5; #end
#ifndef (MIN_REUSE) #declare MIN_REUSE = 0.005; #end
#ifndef (RAD_ADC) #declare RAD_ADC = 0.001; #end

global_settings {
  assumed_gamma 1.0
  ambient_light 0
  max_trace_level 32
  radiosity {
    count COUNT
    nearest_count NEAREST
    error_bound ERROR_BOUND
    recursion_limit RECURSION
    pretrace_start PRETRACE_START
    pretrace_end PRETRACE_END
    low_error_factor LOW_ERROR
    minimum_reuse MIN_REUSE
    adc_bailout RAD_ADC
    always_sample off
    normal on
    media off
    brightness 1
    gray_threshold 0
    max_sample -1
  }
}

background { rgb 0 }

camera {
  perspective
  location <0, 0, -3.9>
  look_at <0, 0, 0>
  right x
  up y
  angle 39.3077
}

#declare Diffuse = finish { diffuse 1 ambient 0 emission 0 specular 0 phong 0 };
#declare T_White = texture { pigment { rgb <0.885809, 0.698859, 0.666422> } finish { Diffuse } };
#declare T_Green = texture { pigment { rgb <0.105421, 0.37798, 0.076425> } finish { Diffuse } };
#declare T_Red = texture { pigment { rgb <0.570068, 0.0430135, 0.0443706> } finish { Diffuse } };
#declare T_Light = texture {
  pigment { rgb <0.885809, 0.698859, 0.666422> }
  finish { diffuse 1 ambient 0 emission <20.757296, 20.014481, 10.134074> specular 0 phong 0 }
};
#declare T_Black = texture { pigment { rgb 0 } finish { diffuse 0 ambient 0 emission 0 } };

// The objects of cornell.json in its order, z negated: floor, ceiling, back wall, right (green)
// and left (red) walls, the lamp, the short block (5 faces and its bottom), the tall block.
union {
  triangle { <-1, -1, -1>, <1, -1, -1>, <1, -1, 1> texture { T_White } }
  triangle { <-1, -1, -1>, <1, -1, 1>, <-1, -1, 1> texture { T_White } }
  triangle { <-1, 1, 1>, <1, 1, 1>, <1, 1, -1> texture { T_White } }
  triangle { <-1, 1, 1>, <1, 1, -1>, <-1, 1, -1> texture { T_White } }
  triangle { <-1, -1, 1>, <1, -1, 1>, <1, 1, 1> texture { T_White } }
  triangle { <-1, -1, 1>, <1, 1, 1>, <-1, 1, 1> texture { T_White } }
  triangle { <1, -1, 1>, <1, -1, -1>, <1, 1, -1> texture { T_Green } }
  triangle { <1, -1, 1>, <1, 1, -1>, <1, 1, 1> texture { T_Green } }
  triangle { <-1, -1, -1>, <-1, -1, 1>, <-1, 1, 1> texture { T_Red } }
  triangle { <-1, -1, -1>, <-1, 1, 1>, <-1, 1, -1> texture { T_Red } }
  triangle { <-0.23, 0.99, 0.18>, <0.23, 0.99, 0.18>, <0.23, 0.99, -0.2>
             texture { T_Light } interior_texture { T_Black } }
  triangle { <-0.23, 0.99, 0.18>, <0.23, 0.99, -0.2>, <-0.23, 0.99, -0.2>
             texture { T_Light } interior_texture { T_Black } }
  triangle { <-0.039603, -1, -0.57918>, <0.53418, -1, -0.754603>, <0.53418, -0.4, -0.754603> texture { T_White } }
  triangle { <-0.039603, -1, -0.57918>, <0.53418, -0.4, -0.754603>, <-0.039603, -0.4, -0.57918> texture { T_White } }
  triangle { <0.709603, -1, -0.18082>, <0.13582, -1, -0.005397>, <0.13582, -0.4, -0.005397> texture { T_White } }
  triangle { <0.709603, -1, -0.18082>, <0.13582, -0.4, -0.005397>, <0.709603, -0.4, -0.18082> texture { T_White } }
  triangle { <0.53418, -1, -0.754603>, <0.709603, -1, -0.18082>, <0.709603, -0.4, -0.18082> texture { T_White } }
  triangle { <0.53418, -1, -0.754603>, <0.709603, -0.4, -0.18082>, <0.53418, -0.4, -0.754603> texture { T_White } }
  triangle { <0.13582, -1, -0.005397>, <-0.039603, -1, -0.57918>, <-0.039603, -0.4, -0.57918> texture { T_White } }
  triangle { <0.13582, -1, -0.005397>, <-0.039603, -0.4, -0.57918>, <0.13582, -0.4, -0.005397> texture { T_White } }
  triangle { <-0.039603, -0.4, -0.57918>, <0.53418, -0.4, -0.754603>, <0.709603, -0.4, -0.18082> texture { T_White } }
  triangle { <-0.039603, -0.4, -0.57918>, <0.709603, -0.4, -0.18082>, <0.13582, -0.4, -0.005397> texture { T_White } }
  triangle { <0.13582, -1, -0.005397>, <0.709603, -1, -0.18082>, <0.53418, -1, -0.754603> texture { T_White } }
  triangle { <0.13582, -1, -0.005397>, <0.53418, -1, -0.754603>, <-0.039603, -1, -0.57918> texture { T_White } }
  triangle { <-0.520961, -1.01, -0.098859>, <0.048859, -1.01, 0.089039>, <0.048859, 0.21, 0.089039> texture { T_White } }
  triangle { <-0.520961, -1.01, -0.098859>, <0.048859, 0.21, 0.089039>, <-0.520961, 0.21, -0.098859> texture { T_White } }
  triangle { <-0.139039, -1.01, 0.658859>, <-0.708859, -1.01, 0.470961>, <-0.708859, 0.21, 0.470961> texture { T_White } }
  triangle { <-0.139039, -1.01, 0.658859>, <-0.708859, 0.21, 0.470961>, <-0.139039, 0.21, 0.658859> texture { T_White } }
  triangle { <0.048859, -1.01, 0.089039>, <-0.139039, -1.01, 0.658859>, <-0.139039, 0.21, 0.658859> texture { T_White } }
  triangle { <0.048859, -1.01, 0.089039>, <-0.139039, 0.21, 0.658859>, <0.048859, 0.21, 0.089039> texture { T_White } }
  triangle { <-0.708859, -1.01, 0.470961>, <-0.520961, -1.01, -0.098859>, <-0.520961, 0.21, -0.098859> texture { T_White } }
  triangle { <-0.708859, -1.01, 0.470961>, <-0.520961, 0.21, -0.098859>, <-0.708859, 0.21, 0.470961> texture { T_White } }
  triangle { <-0.520961, 0.21, -0.098859>, <0.048859, 0.21, 0.089039>, <-0.139039, 0.21, 0.658859> texture { T_White } }
  triangle { <-0.520961, 0.21, -0.098859>, <-0.139039, 0.21, 0.658859>, <-0.708859, 0.21, 0.470961> texture { T_White } }
  triangle { <-0.708859, -1.01, 0.470961>, <-0.139039, -1.01, 0.658859>, <0.048859, -1.01, 0.089039> texture { T_White } }
  triangle { <-0.708859, -1.01, 0.470961>, <0.048859, -1.01, 0.089039>, <-0.520961, -1.01, -0.098859> texture { T_White } }
}
