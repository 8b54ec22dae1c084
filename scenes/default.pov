// default.pov: circe's default scene — the Lee Perry-Smith head scan (Infinite-Realities, CC BY 3.0;
// see assets/lee_perry_smith_head/) in skin with its colour and normal maps, lit by a sphere light
// and a studio environment.
#version 3.7;

// The scan is about 8.6 units from ear to ear, a real head about 19 cm: 22 mm per unit.
global_settings { mm_per_unit 22 max_trace_level 6 }

camera {
  location <4.5, 1.5, 17>
  look_at <0, 0.6, 0>
  angle 34
}

// A warm key light above and to the side of the camera; the environment fills the rest.
light_source { <-10, 12, 16> color rgb <1, 0.94, 0.86> intensity 450 radius 1.5 }
sky_sphere { image "assets/studio/studio.exr" intensity 0.5 }

mesh {
  file "assets/lee_perry_smith_head/LeePerrySmith.obj"
  material {
    skin {
      image "assets/lee_perry_smith_head/Map-COL.jpg"
      normal_map "assets/lee_perry_smith_head/Infinite-Level_02_Tangent_SmoothUV.jpg" strength 1
    }
  }
}
