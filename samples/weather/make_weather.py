#!/usr/bin/env python3
"""Writes the sample weather files: a synthetic typical year for three sites, as EPW.

  python3 samples/weather/make_weather.py      (writes samples/weather/*.epw)

These are NOT measured weather and NOT a published typical meteorological year. They are a
documented synthetic year, made so that radbake's annual daylight can be run and tested on any
machine without downloading weather (nothing may download at run time):

- The sun: declination and equation of time by Spencer (1971), at the middle of each hour of local
  standard time; extraterrestrial normal irradiance 1367 W/m2 x (1 + 0.033 cos(2 pi day / 365)).
- The day's clearness index kt: a monthly mean chosen to resemble the climate (values below, an
  assumption of this script, not data), plus a first-order autoregressive day-to-day swing
  (correlation 0.5, spread 0.12), from a fixed seed per site, clipped to 0.05..0.78.
- Each hour: global horizontal = kt x extraterrestrial horizontal, with a +-8% hourly swing; the
  diffuse share by Erbs, Klein and Duffie (1982) from the hour's kt; direct normal = (global -
  diffuse) / cos(zenith), at most 0.85 of extraterrestrial.
- Illuminance fields (not read by radbake): irradiance x 110 (global), 100 (direct), 120 (diffuse)
  lm/W. Dew point: a monthly value (an assumption); dry bulb dew point + 6 C; other fields
  plausible constants. Hours with the sun down are dark.
"""
import math
import os
import random

HERE = os.path.dirname(os.path.abspath(__file__))

# name, country, latitude, longitude (east +), UTC offset, elevation m, monthly mean kt, dew point C
SITES = [
    ("London", "GBR", 51.51, -0.13, 0.0, 11,
     [0.30, 0.35, 0.38, 0.42, 0.45, 0.45, 0.46, 0.44, 0.42, 0.37, 0.32, 0.28],
     [2, 2, 3, 4, 7, 10, 12, 12, 10, 8, 5, 3]),
    ("Madrid", "ESP", 40.42, -3.70, 1.0, 667,
     [0.50, 0.53, 0.57, 0.58, 0.60, 0.66, 0.70, 0.68, 0.62, 0.55, 0.50, 0.47],
     [1, 1, 2, 4, 7, 9, 10, 10, 9, 7, 4, 2]),
    ("Singapore", "SGP", 1.35, 103.82, 8.0, 15,
     [0.45, 0.50, 0.50, 0.48, 0.47, 0.48, 0.47, 0.47, 0.46, 0.45, 0.42, 0.42],
     [23, 23, 24, 24, 24, 24, 24, 24, 24, 24, 24, 23]),
]
DAYS = [31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31]


def sun(latitude, longitude, utc_offset, day_of_year, clock_hour):
    """cos(zenith) at a local standard clock time (Spencer 1971)."""
    g = 2 * math.pi * (day_of_year - 1) / 365
    declination = (0.006918 - 0.399912 * math.cos(g) + 0.070257 * math.sin(g) - 0.006758 * math.cos(2 * g) +
                   0.000907 * math.sin(2 * g) - 0.002697 * math.cos(3 * g) + 0.00148 * math.sin(3 * g))
    equation_of_time = 229.18 * (0.000075 + 0.001868 * math.cos(g) - 0.032077 * math.sin(g) -
                                 0.014615 * math.cos(2 * g) - 0.040849 * math.sin(2 * g))  # minutes
    solar_time = clock_hour + (equation_of_time + 4 * longitude - 60 * utc_offset) / 60
    hour_angle = math.radians(15 * (solar_time - 12))
    lat = math.radians(latitude)
    return math.sin(lat) * math.sin(declination) + math.cos(lat) * math.cos(declination) * math.cos(hour_angle)


def erbs_diffuse_share(kt):
    if kt <= 0.22:
        return 1 - 0.09 * kt
    if kt <= 0.80:
        return 0.9511 - 0.1604 * kt + 4.388 * kt ** 2 - 16.638 * kt ** 3 + 12.336 * kt ** 4
    return 0.165


def write_site(name, country, latitude, longitude, utc_offset, elevation, kt_month, dew_month):
    rng = random.Random(name)
    lines = ["LOCATION,%s,-,%s,radbake synthetic year (samples/weather/make_weather.py),000000,%.2f,%.2f,%.1f,%.1f" % (
                 name, country, latitude, longitude, utc_offset, elevation),
             "DESIGN CONDITIONS,0", "TYPICAL/EXTREME PERIODS,0", "GROUND TEMPERATURES,0",
             "HOLIDAYS/DAYLIGHT SAVINGS,No,0,0,0",
             "COMMENTS 1,Synthetic weather for radbake's tests and samples: not measured data; see make_weather.py",
             "COMMENTS 2,Monthly clearness indices and dew points are assumptions of the script",
             "DATA PERIODS,1,1,Data,Sunday, 1/ 1,12/31"]
    swing = 0.0
    day_of_year = 0
    for month in range(1, 13):
        for day in range(1, DAYS[month - 1] + 1):
            day_of_year += 1
            swing = 0.5 * swing + rng.gauss(0, 0.12)
            kt_day = min(0.78, max(0.05, kt_month[month - 1] + swing))
            e0n = 1367 * (1 + 0.033 * math.cos(2 * math.pi * day_of_year / 365))
            for hour in range(1, 25):
                cos_z = sun(latitude, longitude, utc_offset, day_of_year, hour - 0.5)
                ghi = dhi = dni = 0.0
                if cos_z > 0.01:
                    kt = min(0.8, max(0.02, kt_day * (1 + rng.uniform(-0.08, 0.08))))
                    ghi = kt * e0n * cos_z
                    dhi = min(ghi, erbs_diffuse_share(kt) * ghi)
                    dni = min(0.85 * e0n, (ghi - dhi) / cos_z)
                    ghi = dhi + dni * cos_z
                dew = dew_month[month - 1]
                lines.append("2025,%d,%d,%d,60,radbake,%.1f,%.1f,70,101325,0,0,300,%d,%d,%d,%d,%d,%d,0,0,2.0,5,5,20,99999,9,"
                             "999999999,20,0.1,0,88,0.2,0,0" % (
                                 month, day, hour, dew + 6, dew, round(ghi), round(dni), round(dhi),
                                 round(110 * ghi), round(100 * dni), round(120 * dhi)))
    path = os.path.join(HERE, "%s_synthetic.epw" % name.lower())
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote", os.path.relpath(path))


if __name__ == "__main__":
    for site in SITES:
        write_site(*site)
