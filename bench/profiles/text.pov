// The text of bench/profiles/text.kerf as POV-Ray's text object (the same font file).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -6> look_at <0, 0, 0> angle 51.3 right x*4/3 }
light_source { <5, 20, -10> color rgb 1 }
background { color rgb 0 }
text { ttf "timrom.ttf" "POV-Ray kerf" 0.3, 0
  translate <-2.9, -0.33, 0>
  pigment { color rgb <1, 0.8, 0.2> } finish { diffuse 0.7 phong 0.5 }
}
plane { y, -1 pigment { color rgb 1 } }
