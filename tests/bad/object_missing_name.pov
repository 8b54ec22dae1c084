// object { } holds a declared object or an object, not a number.
object { 1 }
