// POV-Ray's omnimax camera (camera/omnimax.pov): the projection after it in the dump.
camera { omnimax location <5, 3, 8> look_at <0, 4, 2> }
sphere { 0, 1 }
