// bench/many_lights.pov: 40 small sphere lights of random colours and intensities (seed 3) about a
// diffuse sphere, a box and a plane: the light tree's case (more than LIGHT_SET_LOCAL_MAX lights).
#version 3.7;
camera { location <0, 4, -12> look_at <0, 0.5, 0> angle 45 }
background { color rgb 0.02 }
plane { y, 0 material { diffuse { color rgb 0.6 } } }
sphere { <0, 1, 0>, 1 material { diffuse { color rgb <0.8, 0.6, 0.5> } } }
box { <-3, 0, 1>, <-2, 2, 2> material { diffuse { color rgb 0.7 } } }
light_source { <-4.19, 1.79, 1.62> color rgb <0.68, 0.70, 0.25> intensity 2.2 radius 0.2 }
light_source { <5.40, 1.32, -2.37> color rgb <1.00, 0.58, 0.87> intensity 10.6 radius 0.2 }
light_source { <2.23, 2.72, -3.89> color rgb <0.89, 0.62, 0.79> intensity 14.1 radius 0.2 }
light_source { <-6.98, 2.57, 4.62> color rgb <0.44, 0.22, 0.89> intensity 10.5 radius 0.2 }
light_source { <3.50, 3.00, 6.30> color rgb <0.94, 0.52, 0.84> intensity 10.0 radius 0.2 }
light_source { <6.97, 0.84, 6.30> color rgb <0.31, 0.37, 0.97> intensity 9.9 radius 0.2 }
light_source { <2.03, 2.28, -1.79> color rgb <0.51, 0.48, 0.67> intensity 12.5 radius 0.2 }
light_source { <6.47, 3.75, 3.55> color rgb <0.89, 0.99, 0.74> intensity 4.9 radius 0.2 }
light_source { <5.77, 3.67, 7.50> color rgb <0.66, 0.77, 0.37> intensity 17.0 radius 0.2 }
light_source { <1.18, 0.72, -2.01> color rgb <0.88, 0.99, 0.27> intensity 16.4 radius 0.2 }
light_source { <-1.43, 1.53, -3.89> color rgb <0.82, 0.90, 0.24> intensity 13.1 radius 0.2 }
light_source { <-7.28, 1.66, 4.06> color rgb <0.90, 0.98, 0.60> intensity 20.0 radius 0.2 }
light_source { <-3.05, 2.60, -4.92> color rgb <0.23, 0.36, 0.53> intensity 13.0 radius 0.2 }
light_source { <-5.50, 3.54, -5.41> color rgb <0.45, 0.97, 0.92> intensity 8.8 radius 0.2 }
light_source { <-0.63, 2.75, 1.28> color rgb <0.68, 0.65, 0.70> intensity 18.9 radius 0.2 }
light_source { <0.11, 3.02, 0.04> color rgb <0.39, 0.44, 0.98> intensity 11.4 radius 0.2 }
light_source { <0.77, 1.95, -5.84> color rgb <0.66, 0.22, 0.69> intensity 13.4 radius 0.2 }
light_source { <-7.04, 2.13, 2.78> color rgb <0.74, 0.48, 0.77> intensity 15.3 radius 0.2 }
light_source { <-7.65, 2.87, -5.15> color rgb <0.97, 0.40, 0.57> intensity 12.7 radius 0.2 }
light_source { <-2.88, 1.59, -0.90> color rgb <0.50, 0.68, 0.44> intensity 8.8 radius 0.2 }
light_source { <4.36, 2.49, -5.62> color rgb <0.79, 0.45, 0.38> intensity 16.5 radius 0.2 }
light_source { <-4.18, 2.02, -3.38> color rgb <0.76, 0.28, 0.46> intensity 8.0 radius 0.2 }
light_source { <5.34, 3.49, 0.14> color rgb <0.34, 0.47, 0.72> intensity 17.9 radius 0.2 }
light_source { <-0.78, 0.92, -2.85> color rgb <0.62, 0.35, 0.85> intensity 17.1 radius 0.2 }
light_source { <-5.06, 3.33, -2.10> color rgb <0.71, 0.85, 0.48> intensity 4.3 radius 0.2 }
light_source { <-3.33, 1.45, 5.11> color rgb <0.48, 0.53, 0.54> intensity 9.4 radius 0.2 }
light_source { <6.73, 0.52, -3.82> color rgb <0.95, 0.90, 0.99> intensity 9.8 radius 0.2 }
light_source { <7.20, 1.28, 6.98> color rgb <0.80, 0.87, 0.73> intensity 11.3 radius 0.2 }
light_source { <-3.38, 1.30, -1.23> color rgb <0.25, 0.67, 0.43> intensity 16.6 radius 0.2 }
light_source { <-7.28, 2.93, 6.65> color rgb <0.94, 0.92, 0.92> intensity 12.4 radius 0.2 }
light_source { <-7.79, 1.10, 4.43> color rgb <0.44, 0.73, 0.62> intensity 9.4 radius 0.2 }
light_source { <7.02, 1.69, 2.57> color rgb <0.40, 0.89, 0.58> intensity 16.1 radius 0.2 }
light_source { <-2.37, 2.37, -3.24> color rgb <0.85, 0.34, 0.83> intensity 18.6 radius 0.2 }
light_source { <4.90, 0.53, 5.53> color rgb <0.70, 0.89, 0.24> intensity 6.9 radius 0.2 }
light_source { <-3.70, 1.98, 1.38> color rgb <0.58, 0.82, 0.20> intensity 3.0 radius 0.2 }
light_source { <-5.97, 0.74, -4.26> color rgb <0.98, 0.88, 0.27> intensity 11.0 radius 0.2 }
light_source { <-2.95, 1.73, -1.60> color rgb <0.72, 0.67, 0.49> intensity 5.4 radius 0.2 }
light_source { <-2.74, 2.44, -4.27> color rgb <0.77, 0.50, 0.26> intensity 5.2 radius 0.2 }
light_source { <-2.03, 3.24, 2.46> color rgb <0.50, 0.84, 0.70> intensity 9.8 radius 0.2 }
light_source { <-2.04, 2.96, 0.95> color rgb <0.54, 0.76, 0.57> intensity 6.4 radius 0.2 }
