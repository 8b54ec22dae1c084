// camera { Name } needs a declared camera.
#declare T = transform { translate x }
camera { T }
