#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <2, 3, -4> look_at <0, 0.5, 0> angle 40*4/3 }
light_source { <-2, 5, -3> color rgb 1 }
prism { linear_sweep linear_spline 0, 1, 6, <-1,-1>,<1,-1>,<1.3,0.4>,<0,1.2>,<-1.3,0.4>,<-1,-1> pigment { rgb 0.8 } }
