//! Numbers in a message, as the message's language writes them: its decimal mark
//! and its digit grouping (`1,234.5` in English, `1 234,5` in French), from the
//! Unicode CLDR data that ICU4X carries. Fluent chooses how many decimals (the
//! message's `NUMBER($x, maximumFractionDigits: 2)`); this writes them.

use fixed_decimal::{Decimal, FloatPrecision, SignedRoundingMode, UnsignedRoundingMode};
use fluent_bundle::FluentValue;
use fluent_bundle::memoizer::MemoizerKind;
use fluent_bundle::types::FluentNumber;
use icu_decimal::options::GroupingStrategy;
use icu_decimal::{DecimalFormatter, DecimalFormatterPreferences};
use intl_memoizer::Memoizable;
use unic_langid::LanguageIdentifier;

/// The catalogue's number writer, which Fluent calls for every value it places in a
/// message: a number in the message's language; `None` (Fluent's own writing) for
/// anything else, and for numbers with no decimal form (infinities, NaN).
pub fn write<M: MemoizerKind>(value: &FluentValue, memoizer: &M) -> Option<String> {
    let FluentValue::Number(number) = value else {
        return None;
    };
    let decimal = decimal(number)?;
    let grouping = number.options.use_grouping;
    memoizer
        .with_try_get_threadsafe::<Writer, _, _>((grouping,), |writer| {
            writer.0.format(&decimal).to_string()
        })
        .ok()
}

/// `number` as a decimal with the digits its options ask for: rounded to at most
/// `maximumFractionDigits` decimals (half away from zero, as JavaScript's `Intl`
/// does: 0.005 is 0.01) and padded to at least `minimumFractionDigits`;
/// without them, the shortest decimal that reads back as the same number.
fn decimal(number: &FluentNumber) -> Option<Decimal> {
    let mut decimal = Decimal::try_from_f64(number.value, FloatPrecision::RoundTrip).ok()?;
    if let Some(most) = number.options.maximum_fraction_digits {
        let half_away_from_zero = SignedRoundingMode::Unsigned(UnsignedRoundingMode::HalfExpand);
        decimal.round_with_mode(-position(most), half_away_from_zero);
    }
    if let Some(least) = number.options.minimum_fraction_digits {
        decimal.absolute.pad_end(-position(least));
    }
    Some(decimal)
}

/// A count of decimals as a digit position (at most 20: f64 has no more).
fn position(decimals: usize) -> i16 {
    decimals.min(20) as i16
}

/// ICU4X's decimal writer for one language, with or without digit grouping; Fluent
/// keeps one per language and grouping.
struct Writer(DecimalFormatter);

impl Memoizable for Writer {
    type Args = (bool,);
    type Error = String;

    fn construct(language: LanguageIdentifier, (grouping,): (bool,)) -> Result<Self, String> {
        let locale: icu_locale_core::Locale =
            language.to_string().parse().map_err(|e| format!("{e:?}"))?;
        let strategy = if grouping {
            GroupingStrategy::Auto
        } else {
            GroupingStrategy::Never
        };
        DecimalFormatter::try_new(DecimalFormatterPreferences::from(&locale), strategy.into())
            .map(Writer)
            .map_err(|e| e.to_string())
    }
}
