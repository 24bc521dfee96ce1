// The goblet of bench/profiles/goblet.kerf as POV-Ray's lathe with a Bézier spline: lines as
// cubics with doubled ends, quadratics raised to cubics (4 points a segment).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.8, -3> look_at <0, 0.7, 0> angle 51.3 right x*4/3 }
light_source { <5, 20, -10> color rgb 1 }
background { color rgb 0 }
lathe {
  bezier_spline 28,
  <0, 0>, <0, 0>, <0.5, 0>, <0.5, 0>,
  <0.5, 0>, <0.5, 0.0533333>, <0.366667, 0.0866667>, <0.1, 0.1>,
  <0.1, 0.1>, <0.1, 0.1>, <0.08, 0.7>, <0.08, 0.7>,
  <0.08, 0.7>, <0.6, 0.75>, <0.6, 1.2>, <0.55, 1.4>,
  <0.55, 1.4>, <0.533333, 1.43333>, <0.516667, 1.43333>, <0.5, 1.4>,
  <0.5, 1.4>, <0.5, 1.2>, <0.5, 0.85>, <0, 0.82>,
  <0, 0.82>, <0, 0.82>, <0, 0>, <0, 0>
  pigment { color rgb <0.3, 0.5, 0.8> } finish { diffuse 0.8 phong 0.4 }
}
plane { y, 0 pigment { color rgb 1 } }
