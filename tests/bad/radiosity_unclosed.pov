// A radiosity block of global_settings with more "{" than "}": the file ends inside it.
global_settings {
  radiosity {
    count 100 nearest_count 5
    media { off }
    brightness { 1
}
