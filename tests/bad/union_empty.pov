union { translate x }
