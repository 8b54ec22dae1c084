// fog_type is 1 (constant) or 2 (ground).
fog { fog_type 3 distance 10 }
