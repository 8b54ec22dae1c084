// A fog without its distance: POV-Ray renders nothing of it; circe asks for it.
fog { color rgb 0.5 }
