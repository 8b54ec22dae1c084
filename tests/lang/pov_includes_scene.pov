// pov_includes: POV-Ray 3.7's colors.inc (every colour it declares, printed), strings.inc and
// arrays.inc macros in use, colors.inc's colour-space macros; tests/lang/pov_includes.sh compares the output with pov_includes_scene.stderr
// which povray 3.7.0 printed alike.
#include "colors.inc"
#include "strings.inc"
#include "arrays.inc"
#include "consts.inc"
#include "rand.inc"
#declare N = 0;
#debug concat("Red ", CRGBFTStr(Red, 0, 3), "\n") #declare N = N + 1;
#debug concat("Green ", CRGBFTStr(Green, 0, 3), "\n") #declare N = N + 1;
#debug concat("Blue ", CRGBFTStr(Blue, 0, 3), "\n") #declare N = N + 1;
#debug concat("Yellow ", CRGBFTStr(Yellow, 0, 3), "\n") #declare N = N + 1;
#debug concat("Cyan ", CRGBFTStr(Cyan, 0, 3), "\n") #declare N = N + 1;
#debug concat("Magenta ", CRGBFTStr(Magenta, 0, 3), "\n") #declare N = N + 1;
#debug concat("Clear ", CRGBFTStr(Clear, 0, 3), "\n") #declare N = N + 1;
#debug concat("White ", CRGBFTStr(White, 0, 3), "\n") #declare N = N + 1;
#debug concat("Black ", CRGBFTStr(Black, 0, 3), "\n") #declare N = N + 1;
#debug concat("Gray05 ", CRGBFTStr(Gray05, 0, 3), "\n") #declare N = N + 1;
#debug concat("Gray10 ", CRGBFTStr(Gray10, 0, 3), "\n") #declare N = N + 1;
#debug concat("Gray15 ", CRGBFTStr(Gray15, 0, 3), "\n") #declare N = N + 1;
#debug concat("Gray20 ", CRGBFTStr(Gray20, 0, 3), "\n") #declare N = N + 1;
#debug concat("Gray25 ", CRGBFTStr(Gray25, 0, 3), "\n") #declare N = N + 1;
#debug concat("Gray30 ", CRGBFTStr(Gray30, 0, 3), "\n") #declare N = N + 1;
#debug concat("Gray35 ", CRGBFTStr(Gray35, 0, 3), "\n") #declare N = N + 1;
#debug concat("Gray40 ", CRGBFTStr(Gray40, 0, 3), "\n") #declare N = N + 1;
#debug concat("Gray45 ", CRGBFTStr(Gray45, 0, 3), "\n") #declare N = N + 1;
#debug concat("Gray50 ", CRGBFTStr(Gray50, 0, 3), "\n") #declare N = N + 1;
#debug concat("Gray55 ", CRGBFTStr(Gray55, 0, 3), "\n") #declare N = N + 1;
#debug concat("Gray60 ", CRGBFTStr(Gray60, 0, 3), "\n") #declare N = N + 1;
#debug concat("Gray65 ", CRGBFTStr(Gray65, 0, 3), "\n") #declare N = N + 1;
#debug concat("Gray70 ", CRGBFTStr(Gray70, 0, 3), "\n") #declare N = N + 1;
#debug concat("Gray75 ", CRGBFTStr(Gray75, 0, 3), "\n") #declare N = N + 1;
#debug concat("Gray80 ", CRGBFTStr(Gray80, 0, 3), "\n") #declare N = N + 1;
#debug concat("Gray85 ", CRGBFTStr(Gray85, 0, 3), "\n") #declare N = N + 1;
#debug concat("Gray90 ", CRGBFTStr(Gray90, 0, 3), "\n") #declare N = N + 1;
#debug concat("Gray95 ", CRGBFTStr(Gray95, 0, 3), "\n") #declare N = N + 1;
#debug concat("DimGray ", CRGBFTStr(DimGray, 0, 3), "\n") #declare N = N + 1;
#debug concat("DimGrey ", CRGBFTStr(DimGrey, 0, 3), "\n") #declare N = N + 1;
#debug concat("Gray ", CRGBFTStr(Gray, 0, 3), "\n") #declare N = N + 1;
#debug concat("Grey ", CRGBFTStr(Grey, 0, 3), "\n") #declare N = N + 1;
#debug concat("LightGray ", CRGBFTStr(LightGray, 0, 3), "\n") #declare N = N + 1;
#debug concat("LightGrey ", CRGBFTStr(LightGrey, 0, 3), "\n") #declare N = N + 1;
#debug concat("VLightGray ", CRGBFTStr(VLightGray, 0, 3), "\n") #declare N = N + 1;
#debug concat("VLightGrey ", CRGBFTStr(VLightGrey, 0, 3), "\n") #declare N = N + 1;
#debug concat("Aquamarine ", CRGBFTStr(Aquamarine, 0, 3), "\n") #declare N = N + 1;
#debug concat("BlueViolet ", CRGBFTStr(BlueViolet, 0, 3), "\n") #declare N = N + 1;
#debug concat("Brown ", CRGBFTStr(Brown, 0, 3), "\n") #declare N = N + 1;
#debug concat("CadetBlue ", CRGBFTStr(CadetBlue, 0, 3), "\n") #declare N = N + 1;
#debug concat("Coral ", CRGBFTStr(Coral, 0, 3), "\n") #declare N = N + 1;
#debug concat("CornflowerBlue ", CRGBFTStr(CornflowerBlue, 0, 3), "\n") #declare N = N + 1;
#debug concat("DarkGreen ", CRGBFTStr(DarkGreen, 0, 3), "\n") #declare N = N + 1;
#debug concat("DarkOliveGreen ", CRGBFTStr(DarkOliveGreen, 0, 3), "\n") #declare N = N + 1;
#debug concat("DarkOrchid ", CRGBFTStr(DarkOrchid, 0, 3), "\n") #declare N = N + 1;
#debug concat("DarkSlateBlue ", CRGBFTStr(DarkSlateBlue, 0, 3), "\n") #declare N = N + 1;
#debug concat("DarkSlateGray ", CRGBFTStr(DarkSlateGray, 0, 3), "\n") #declare N = N + 1;
#debug concat("DarkSlateGrey ", CRGBFTStr(DarkSlateGrey, 0, 3), "\n") #declare N = N + 1;
#debug concat("DarkTurquoise ", CRGBFTStr(DarkTurquoise, 0, 3), "\n") #declare N = N + 1;
#debug concat("Firebrick ", CRGBFTStr(Firebrick, 0, 3), "\n") #declare N = N + 1;
#debug concat("ForestGreen ", CRGBFTStr(ForestGreen, 0, 3), "\n") #declare N = N + 1;
#debug concat("Gold ", CRGBFTStr(Gold, 0, 3), "\n") #declare N = N + 1;
#debug concat("Goldenrod ", CRGBFTStr(Goldenrod, 0, 3), "\n") #declare N = N + 1;
#debug concat("GreenYellow ", CRGBFTStr(GreenYellow, 0, 3), "\n") #declare N = N + 1;
#debug concat("IndianRed ", CRGBFTStr(IndianRed, 0, 3), "\n") #declare N = N + 1;
#debug concat("Khaki ", CRGBFTStr(Khaki, 0, 3), "\n") #declare N = N + 1;
#debug concat("LightBlue ", CRGBFTStr(LightBlue, 0, 3), "\n") #declare N = N + 1;
#debug concat("LightSteelBlue ", CRGBFTStr(LightSteelBlue, 0, 3), "\n") #declare N = N + 1;
#debug concat("LimeGreen ", CRGBFTStr(LimeGreen, 0, 3), "\n") #declare N = N + 1;
#debug concat("Maroon ", CRGBFTStr(Maroon, 0, 3), "\n") #declare N = N + 1;
#debug concat("MediumAquamarine ", CRGBFTStr(MediumAquamarine, 0, 3), "\n") #declare N = N + 1;
#debug concat("MediumBlue ", CRGBFTStr(MediumBlue, 0, 3), "\n") #declare N = N + 1;
#debug concat("MediumForestGreen ", CRGBFTStr(MediumForestGreen, 0, 3), "\n") #declare N = N + 1;
#debug concat("MediumGoldenrod ", CRGBFTStr(MediumGoldenrod, 0, 3), "\n") #declare N = N + 1;
#debug concat("MediumOrchid ", CRGBFTStr(MediumOrchid, 0, 3), "\n") #declare N = N + 1;
#debug concat("MediumSeaGreen ", CRGBFTStr(MediumSeaGreen, 0, 3), "\n") #declare N = N + 1;
#debug concat("MediumSlateBlue ", CRGBFTStr(MediumSlateBlue, 0, 3), "\n") #declare N = N + 1;
#debug concat("MediumSpringGreen ", CRGBFTStr(MediumSpringGreen, 0, 3), "\n") #declare N = N + 1;
#debug concat("MediumTurquoise ", CRGBFTStr(MediumTurquoise, 0, 3), "\n") #declare N = N + 1;
#debug concat("MediumVioletRed ", CRGBFTStr(MediumVioletRed, 0, 3), "\n") #declare N = N + 1;
#debug concat("MidnightBlue ", CRGBFTStr(MidnightBlue, 0, 3), "\n") #declare N = N + 1;
#debug concat("Navy ", CRGBFTStr(Navy, 0, 3), "\n") #declare N = N + 1;
#debug concat("NavyBlue ", CRGBFTStr(NavyBlue, 0, 3), "\n") #declare N = N + 1;
#debug concat("Orange ", CRGBFTStr(Orange, 0, 3), "\n") #declare N = N + 1;
#debug concat("OrangeRed ", CRGBFTStr(OrangeRed, 0, 3), "\n") #declare N = N + 1;
#debug concat("Orchid ", CRGBFTStr(Orchid, 0, 3), "\n") #declare N = N + 1;
#debug concat("PaleGreen ", CRGBFTStr(PaleGreen, 0, 3), "\n") #declare N = N + 1;
#debug concat("Pink ", CRGBFTStr(Pink, 0, 3), "\n") #declare N = N + 1;
#debug concat("Plum ", CRGBFTStr(Plum, 0, 3), "\n") #declare N = N + 1;
#debug concat("Salmon ", CRGBFTStr(Salmon, 0, 3), "\n") #declare N = N + 1;
#debug concat("SeaGreen ", CRGBFTStr(SeaGreen, 0, 3), "\n") #declare N = N + 1;
#debug concat("Sienna ", CRGBFTStr(Sienna, 0, 3), "\n") #declare N = N + 1;
#debug concat("SkyBlue ", CRGBFTStr(SkyBlue, 0, 3), "\n") #declare N = N + 1;
#debug concat("SlateBlue ", CRGBFTStr(SlateBlue, 0, 3), "\n") #declare N = N + 1;
#debug concat("SpringGreen ", CRGBFTStr(SpringGreen, 0, 3), "\n") #declare N = N + 1;
#debug concat("SteelBlue ", CRGBFTStr(SteelBlue, 0, 3), "\n") #declare N = N + 1;
#debug concat("Tan ", CRGBFTStr(Tan, 0, 3), "\n") #declare N = N + 1;
#debug concat("Thistle ", CRGBFTStr(Thistle, 0, 3), "\n") #declare N = N + 1;
#debug concat("Turquoise ", CRGBFTStr(Turquoise, 0, 3), "\n") #declare N = N + 1;
#debug concat("Violet ", CRGBFTStr(Violet, 0, 3), "\n") #declare N = N + 1;
#debug concat("VioletRed ", CRGBFTStr(VioletRed, 0, 3), "\n") #declare N = N + 1;
#debug concat("Wheat ", CRGBFTStr(Wheat, 0, 3), "\n") #declare N = N + 1;
#debug concat("YellowGreen ", CRGBFTStr(YellowGreen, 0, 3), "\n") #declare N = N + 1;
#debug concat("SummerSky ", CRGBFTStr(SummerSky, 0, 3), "\n") #declare N = N + 1;
#debug concat("RichBlue ", CRGBFTStr(RichBlue, 0, 3), "\n") #declare N = N + 1;
#debug concat("Brass ", CRGBFTStr(Brass, 0, 3), "\n") #declare N = N + 1;
#debug concat("Copper ", CRGBFTStr(Copper, 0, 3), "\n") #declare N = N + 1;
#debug concat("Bronze ", CRGBFTStr(Bronze, 0, 3), "\n") #declare N = N + 1;
#debug concat("Bronze2 ", CRGBFTStr(Bronze2, 0, 3), "\n") #declare N = N + 1;
#debug concat("Silver ", CRGBFTStr(Silver, 0, 3), "\n") #declare N = N + 1;
#debug concat("BrightGold ", CRGBFTStr(BrightGold, 0, 3), "\n") #declare N = N + 1;
#debug concat("OldGold ", CRGBFTStr(OldGold, 0, 3), "\n") #declare N = N + 1;
#debug concat("Feldspar ", CRGBFTStr(Feldspar, 0, 3), "\n") #declare N = N + 1;
#debug concat("Quartz ", CRGBFTStr(Quartz, 0, 3), "\n") #declare N = N + 1;
#debug concat("Mica ", CRGBFTStr(Mica, 0, 3), "\n") #declare N = N + 1;
#debug concat("NeonPink ", CRGBFTStr(NeonPink, 0, 3), "\n") #declare N = N + 1;
#debug concat("DarkPurple ", CRGBFTStr(DarkPurple, 0, 3), "\n") #declare N = N + 1;
#debug concat("NeonBlue ", CRGBFTStr(NeonBlue, 0, 3), "\n") #declare N = N + 1;
#debug concat("CoolCopper ", CRGBFTStr(CoolCopper, 0, 3), "\n") #declare N = N + 1;
#debug concat("MandarinOrange ", CRGBFTStr(MandarinOrange, 0, 3), "\n") #declare N = N + 1;
#debug concat("LightWood ", CRGBFTStr(LightWood, 0, 3), "\n") #declare N = N + 1;
#debug concat("MediumWood ", CRGBFTStr(MediumWood, 0, 3), "\n") #declare N = N + 1;
#debug concat("DarkWood ", CRGBFTStr(DarkWood, 0, 3), "\n") #declare N = N + 1;
#debug concat("SpicyPink ", CRGBFTStr(SpicyPink, 0, 3), "\n") #declare N = N + 1;
#debug concat("SemiSweetChoc ", CRGBFTStr(SemiSweetChoc, 0, 3), "\n") #declare N = N + 1;
#debug concat("BakersChoc ", CRGBFTStr(BakersChoc, 0, 3), "\n") #declare N = N + 1;
#debug concat("Flesh ", CRGBFTStr(Flesh, 0, 3), "\n") #declare N = N + 1;
#debug concat("NewTan ", CRGBFTStr(NewTan, 0, 3), "\n") #declare N = N + 1;
#debug concat("NewMidnightBlue ", CRGBFTStr(NewMidnightBlue, 0, 3), "\n") #declare N = N + 1;
#debug concat("VeryDarkBrown ", CRGBFTStr(VeryDarkBrown, 0, 3), "\n") #declare N = N + 1;
#debug concat("DarkBrown ", CRGBFTStr(DarkBrown, 0, 3), "\n") #declare N = N + 1;
#debug concat("DarkTan ", CRGBFTStr(DarkTan, 0, 3), "\n") #declare N = N + 1;
#debug concat("GreenCopper ", CRGBFTStr(GreenCopper, 0, 3), "\n") #declare N = N + 1;
#debug concat("DkGreenCopper ", CRGBFTStr(DkGreenCopper, 0, 3), "\n") #declare N = N + 1;
#debug concat("DustyRose ", CRGBFTStr(DustyRose, 0, 3), "\n") #declare N = N + 1;
#debug concat("HuntersGreen ", CRGBFTStr(HuntersGreen, 0, 3), "\n") #declare N = N + 1;
#debug concat("Scarlet ", CRGBFTStr(Scarlet, 0, 3), "\n") #declare N = N + 1;
#debug concat("Med_Purple ", CRGBFTStr(Med_Purple, 0, 3), "\n") #declare N = N + 1;
#debug concat("Light_Purple ", CRGBFTStr(Light_Purple, 0, 3), "\n") #declare N = N + 1;
#debug concat("Very_Light_Purple ", CRGBFTStr(Very_Light_Purple, 0, 3), "\n") #declare N = N + 1;
#debug concat(str(N, 0, 0), " colours\n")
#debug concat(Str(2.5), " ", VStr(<1, 2, 3>), " ", Vstr2D(<1, 2>, 0, 1), "\n")
#declare A = array[6] { 5, 3, 9, 1, 7, 2 }
Sort_Array(A)
#debug concat(str(A[0], 0, 0), str(A[1], 0, 0), str(A[2], 0, 0), str(A[3], 0, 0), str(A[4], 0, 0), str(A[5], 0, 0), "\n")
Reverse_Array(A)
#debug concat(str(A[0], 0, 0), str(A[5], 0, 0), "\n")
Resize_Array(A, 8)
#debug concat(str(dimension_size(A, 1), 0, 0), " ", str(defined(A[7]), 0, 0), "\n")
#declare R = RRand(2, 3, RdmA);
#debug concat(str((R >= 2 & R <= 3), 0, 0), "\n")
// colors.inc's colour-space macros (their ?: and comparisons), strings.inc's triangle strings
#debug concat(CRGBStr(CHSL2RGB(<120, 1, 0.5>), 0, 3), " ", CRGBStr(CHSV2RGB(<300, 0.5, 0.8>), 0, 3), "\n")
#debug concat(CRGBStr(CRGB2HSL(<0.2, 0.4, 0.6>), 0, 3), " ", CRGBStr(CRGB2HSV(<0.9, 0.3, 0.1>), 0, 3), "\n")
#debug concat(Triangle_Str(<0, 0, 0>, <1, 0, 0>, <0, 1, 0>), "\n")
#debug concat(str(Prob(1.5, RdmB), 0, 0), str(Prob(-1, RdmB), 0, 0), "\n")
sphere { 0, 1 }
