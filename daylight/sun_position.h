// Where the sun is, seen from a site at a local date and time: Meeus' solar coordinates
// (Astronomical Algorithms, 2nd ed., ch. 25, 0.01 degree in longitude; ch. 12 for sidereal
// time), with the topocentric parallax and the atmospheric refraction of NREL's SPA report
// (Reda and Andreas 2004, eqs. 37-43). Not SPA's full VSOP87 series (0.0003 degree): a hundredth
// of a degree is 1/50 of the sun's disc.
#pragma once

namespace radbake {

struct SiteAndTime {
  double latitude = 0;       // degrees, north positive
  double longitude = 0;      // degrees, east positive
  double elevation = 0;      // metres above sea level
  double pressure = 1013.25; // mbar, for refraction
  double temperature = 15;   // degrees Celsius, for refraction
  int year = 2000, month = 1, day = 1;
  double hour = 12, minute = 0, second = 0;  // local clock time
  double utc_offset = 0;     // hours: local time minus UTC (UTC-7 is -7)
  double delta_t = 69;       // seconds, terrestrial minus universal time (67 in 2003, 69 in 2020)
};

struct SunPosition {
  double zenith = 0;   // degrees from the zenith, refraction included
  double azimuth = 0;  // degrees from north, eastward (east 90, south 180)
};

SunPosition sun_position(const SiteAndTime& site);

}  // namespace radbake
