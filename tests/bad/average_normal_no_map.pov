// A normal's average needs a normal_map.
sphere { 0, 1 normal { average } }
