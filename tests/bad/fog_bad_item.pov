// An item a fog does not take.
fog { distance 10 color rgb 1 ior 1.5 }
