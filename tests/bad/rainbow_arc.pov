// POV-Ray: "Arc angle is smaller than falloff angle in rainbow."
rainbow { direction z arc_angle 20 falloff_angle 40 }
