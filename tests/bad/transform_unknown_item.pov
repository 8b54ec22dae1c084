// A transform block holds transforms and inverse only.
#declare T = transform { translate x no_shadow }
