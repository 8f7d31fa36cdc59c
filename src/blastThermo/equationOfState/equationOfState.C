/*---------------------------------------------------------------------------*\
  =========                 |
  \\      /  F ield         | jwlIbFoam: rock blasting with OpenFOAM
   \\    /   O peration     |
    \\  /    A nd           |
     \\/     M anipulation  |
\*---------------------------------------------------------------------------*/

#include "equationOfState.H"
#include "OStringStream.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(equationOfState, 0);
    defineRunTimeSelectionTable(equationOfState, dictionary);
}

// Out-of-class definition: the constant may be bound to a reference
constexpr Foam::scalar Foam::equationOfState::noCavitation;


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::equationOfState::readPositive
(
    const dictionary& dict,
    const word& key
)
{
    const scalar value = dict.get<scalar>(key);
    if (!(value > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' must be strictly positive, got "
            << value << exit(FatalIOError);
    }
    return value;
}


Foam::scalar Foam::equationOfState::readPositiveOrDefault
(
    const dictionary& dict,
    const word& key,
    const scalar deflt
)
{
    const scalar value = dict.getOrDefault<scalar>(key, deflt);
    if (!(value > 0))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' must be strictly positive, got "
            << value << exit(FatalIOError);
    }
    return value;
}


void Foam::equationOfState::checkEntries
(
    const dictionary& dict,
    const wordList& valid
) const
{
    for (const entry& e : dict)
    {
        const word key(e.keyword());
        if (key != "equationOfState" && !valid.found(key))
        {
            FatalIOErrorInFunction(dict)
                << "Unknown entry '" << key << "' for material " << name_
                << " (equationOfState "
                << dict.getOrDefault<word>("equationOfState", "?")
                << "). Valid entries: " << valid << exit(FatalIOError);
        }
    }
}


Foam::scalar Foam::equationOfState::readCavitationPressure
(
    const dictionary& dict,
    const scalar deflt
) const
{
    const word key("cavitationPressure");
    const entry* ePtr = dict.findEntry(key, keyType::LITERAL);
    if (!ePtr)
    {
        return deflt;
    }
    if (ePtr->isStream())
    {
        ITstream& is = ePtr->stream();
        if (is.size() == 1)
        {
            const token& t = is[0];
            if (t.isWord() && t.wordToken() == "none")
            {
                return noCavitation;
            }
            if (t.isNumber())
            {
                const scalar value = t.number();
                if (value > 0 && value < VGREAT)
                {
                    return value;
                }
            }
        }
    }
    // What was given, as written (tokens, or 'a dictionary')
    OStringStream given;
    if (ePtr->isStream())
    {
        const ITstream& is = ePtr->stream();
        forAll(is, i)
        {
            given << (i ? " " : "") << is[i];
        }
    }
    else
    {
        given << "a dictionary";
    }
    FatalIOErrorInFunction(dict)
        << "Material " << name_ << ": entry '" << key << "' must be a"
        << " pressure > 0 [Pa] (the liquid's cut-off, e.g. 2300 for water)"
        << " or none, got '" << given.str().c_str() << "'"
        << exit(FatalIOError);
    return deflt;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::equationOfState::equationOfState
(
    const word& name,
    const dictionary& dict
)
:
    name_(name),
    pCav_(noCavitation)
{}


// ************************************************************************* //
