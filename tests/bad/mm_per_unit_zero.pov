global_settings { mm_per_unit 0 }
