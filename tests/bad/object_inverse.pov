// inverse of an object is CSG, outside circe (inverse of a transform is fine).
sphere { 0, 1 transform { translate x inverse } inverse }
