// An item the reflection block does not take.
sphere { 0, 1 finish { reflection { 0.2 roughness 0.1 } } }
