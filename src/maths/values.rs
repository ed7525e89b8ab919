//! Numbers read from scene files, checked as they are read: a value that breaks its
//! rule is refused with a message saying what was expected, and the loader adds the
//! file, key and line.

use serde::{Deserialize, Deserializer};

use crate::maths::{Colour, Real, Vec3};

fn finite(v: Real) -> Result<Real, String> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(format!("expected a finite number, found {v}"))
    }
}

/// Any finite number (an angle that may be negative).
#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(try_from = "Real")]
pub struct Finite(pub Real);

impl TryFrom<Real> for Finite {
    type Error = String;
    fn try_from(v: Real) -> Result<Self, String> {
        finite(v).map(Self)
    }
}

/// A number greater than zero (a radius, a refractive index, a gamma).
#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(try_from = "Real")]
pub struct Positive(pub Real);

impl TryFrom<Real> for Positive {
    type Error = String;
    fn try_from(v: Real) -> Result<Self, String> {
        match finite(v)? {
            v if v > 0.0 => Ok(Self(v)),
            v => Err(format!("expected a number greater than 0, found {v}")),
        }
    }
}

/// A number zero or greater (a light's intensity).
#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(try_from = "Real")]
pub struct NonNegative(pub Real);

impl TryFrom<Real> for NonNegative {
    type Error = String;
    fn try_from(v: Real) -> Result<Self, String> {
        match finite(v)? {
            v if v >= 0.0 => Ok(Self(v)),
            v => Err(format!("expected a number 0 or greater, found {v}")),
        }
    }
}

/// A probability in `(0, 1]` (the survival probability of Russian roulette).
#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(try_from = "Real")]
pub struct Probability(pub Real);

impl TryFrom<Real> for Probability {
    type Error = String;
    fn try_from(v: Real) -> Result<Self, String> {
        match finite(v)? {
            v if v > 0.0 && v <= 1.0 => Ok(Self(v)),
            v => Err(format!(
                "expected a probability above 0 and at most 1, found {v}"
            )),
        }
    }
}

/// A field of view in degrees, strictly between 0 and 180.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(try_from = "Real")]
pub struct Degrees(pub Real);

impl TryFrom<Real> for Degrees {
    type Error = String;
    fn try_from(v: Real) -> Result<Self, String> {
        match finite(v)? {
            v if v > 0.0 && v < 180.0 => Ok(Self(v)),
            v => Err(format!(
                "expected an angle between 0 and 180 degrees, found {v}"
            )),
        }
    }
}

/// A point `[x, y, z]` with finite coordinates.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(try_from = "[Real; 3]")]
pub struct Point(pub Vec3);

impl TryFrom<[Real; 3]> for Point {
    type Error = String;
    fn try_from(v: [Real; 3]) -> Result<Self, String> {
        v.into_iter().try_for_each(|x| finite(x).map(drop))?;
        Ok(Self(Vec3::from_array(v)))
    }
}

/// A colour `[r, g, b]` of finite, non-negative radiance.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(try_from = "[Real; 3]")]
pub struct Rgb(pub Colour);

impl TryFrom<[Real; 3]> for Rgb {
    type Error = String;
    fn try_from(v: [Real; 3]) -> Result<Self, String> {
        for x in v {
            NonNegative::try_from(x)?;
        }
        Ok(Self(Colour::from_array(v)))
    }
}

/// A reflectance `[r, g, b]`, each between 0 and 1: a surface cannot reflect more
/// light than it receives.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(try_from = "[Real; 3]")]
pub struct Albedo(pub Colour);

impl TryFrom<[Real; 3]> for Albedo {
    type Error = String;
    fn try_from(v: [Real; 3]) -> Result<Self, String> {
        for x in v {
            if !(0.0..=1.0).contains(&finite(x)?) {
                return Err(format!("expected an albedo between 0 and 1, found {x}"));
            }
        }
        Ok(Self(Colour::from_array(v)))
    }
}

/// The one field of a scene-file variant such as `{ diffuse = [r, g, b] }`: an
/// [`Albedo`], for `#[serde(deserialize_with)]` on an enum variant.
pub fn albedo<'de, D: Deserializer<'de>>(from: D) -> Result<Colour, D::Error> {
    Albedo::deserialize(from).map(|a| a.0)
}

/// The one field of a scene-file variant such as `{ glass = 1.5 }`: a
/// [`Positive`] number, for `#[serde(deserialize_with)]` on an enum variant.
pub fn positive<'de, D: Deserializer<'de>>(from: D) -> Result<Real, D::Error> {
    Positive::deserialize(from).map(|p| p.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rules_are_enforced() {
        assert!(Positive::try_from(0.0).is_err());
        assert!(Positive::try_from(Real::NAN).is_err());
        assert_eq!(Positive::try_from(2.0), Ok(Positive(2.0)));
        assert!(NonNegative::try_from(-Real::MIN_POSITIVE).is_err());
        assert!(NonNegative::try_from(Real::INFINITY).is_err());
        assert!(Degrees::try_from(180.0).is_err());
        assert!(Probability::try_from(0.0).is_err());
        assert_eq!(Probability::try_from(1.0), Ok(Probability(1.0)));
        assert!(Point::try_from([0.0, Real::NEG_INFINITY, 0.0]).is_err());
        assert!(Rgb::try_from([0.0, -1.0, 0.0]).is_err());
        assert!(Albedo::try_from([0.5, 1.5, 0.0]).is_err());
        assert_eq!(
            Albedo::try_from([0.5, 1.0, 0.0]),
            Ok(Albedo(Colour::new(0.5, 1.0, 0.0)))
        );
    }
}
