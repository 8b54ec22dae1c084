// facets is a normal's pattern only (POV-Ray: Only_In)
sphere { 0, 1 pigment { facets } }
