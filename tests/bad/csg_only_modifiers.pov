difference { translate x }
