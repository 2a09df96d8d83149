#version 3.7;
#declare N = 0;
#while (N < 3)
  #if (mod(N, 2) = 0) sphere { <N, 0, 0>, 0.5 } #elseif (les_per_pixel 4
global_settings {
  width 800 height 600
  render_mode pm
  global_photons 200000
  cauns 20000
  global_estimate { count 100 radius count 60 radius 0.05 }
  max_photon_deph 10
  final_gather 512
  shadow_samples 16
  samples_per_pixel 4
}
#end

//  0.00
// objects outend

// nergy_version)
global_settings {
  width 800 height 600
  render_mode pm
  global_photons 200000
  caustic_photons 200 global_estimate { count 100 radius 5.25 }
  caustic_estimate { count 60 radius 0.05 }
  max_photon_depth 10
  final_gather 512
  shadow_samples 16
  samples_per_pixel 4
}
#end

//  0.00
// objects out