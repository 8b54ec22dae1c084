// POV-Ray directives circe lacks are named.
#default { finish { ambient 0 } }
