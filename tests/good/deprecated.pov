// deprecated: `#declare deprecated [once] ["message"] Name = ...` warns at each use of Name
// (the first only, with once), with the message or POV-Ray's own, as povray 3.7.0 does: a
// #declare of the name again warns and keeps it deprecated, #undef warns, #ifdef does not.
// #version is readable and settable, as include files save and restore it.
// tests/lang/check_cli.sh compares the stderr with deprecated.stderr.
#declare deprecated once "Old is deprecated: use New" Old = 1;
#declare deprecated Y = 2;
#local deprecated once P = pigment { rgb 1 }
#declare A = Old + Old;
#declare B = Y + Y;
#ifdef (Y) #end
sphere { 0, A pigment { P } }
sphere { 0, B pigment { P } }
#declare Y = 3;
#undef Y
#local Saved = version;
#version 3.5;
#if (version != 3.5) #error "#version 3.5 is not read back" #end
#version Saved;
#if (version != 3.7) #error "#version is not restored" #end
