camera { location <0, 0, -5> look_at 0 }
camera { location <0, 0, -5> look_at 0 }
