mesh { translate x }
