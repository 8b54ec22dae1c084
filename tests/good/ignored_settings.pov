// ignored_settings: global_settings items whose work circe does on its own are read and dropped
// with one warning each (ignored_settings.stderr); a radiosity or photons block is skipped with
// its braces matched, whatever it holds. tests/lang/check_cli.sh also checks that the IR is that
// of this scene without the lines between the "ignored" markers.
#declare Gamma = 1.0;
global_settings {
  mm_per_unit 10
  // ignored: begin
  radiosity {
    pretrace_start 0.08 pretrace_end 0.01 count 35 nearest_count 5 error_bound 1.8
    recursion_limit 2 low_error_factor 0.5 gray_threshold 0 minimum_reuse 0.015
    media off normal on always_sample off brightness 1 adc_bailout 0.01 / 2
    #if (Gamma > 0) max_sample 2 #end
  }
  photons { spacing 0.02 autostop 0 jitter 0.4 media 100, 2 expand_thresholds 0.2, 40 save_file "x.ph" }
  // ambient_light is read now (tests/good/pov_finish.pov)
  noise_generator 2
  number_of_waves 10
  charset utf8
  hf_gray_16 on
  adc_bailout 1 / 255
  irid_wavelength rgb <0.25, 0.18, 0.14>
  max_intersections 64
  hf_gray_16
  // ignored: end
  max_trace_level 6
  assumed_gamma Gamma
}
sphere { 0, 1 }
