// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "ConvectionHeatTransfer.H"
#include "coarseGrainFactor.H"
#include "knownKeywords.H"
#include "keywordSource.H"

template<class CloudType>
Foam::dictionary Foam::ConvectionHeatTransfer<CloudType>::withoutBird
(
    const dictionary& dict
)
{
    const word coeffs(typeName + "Coeffs");
    if (!dict.isDict(coeffs))
    {
        FatalIOErrorInFunction(dict)
            << "heatTransferModel " << typeName << " in " << dict.name()
            << " needs the dictionary " << coeffs << " with the keyword law"
            << " (Gunn or RanzMarshall)" << exit(FatalIOError);
    }
    const dictionary& given = dict.subDict(coeffs);
    if (given.lookupOrDefault<bool>("BirdCorrection", false))
    {
        FatalIOErrorInKeyword(given, "BirdCorrection")
            << "Keyword BirdCorrection in " << given.name()
            << " must be false: the parcels exchange no mass"
            << exit(FatalIOError);
    }
    knownKeywords::check(given, {"law", "voidage", "BirdCorrection"});
    dictionary patched(dict);
    patched.subDict(coeffs).set("BirdCorrection", false);
    // A copy made in the return slot: a moved dictionary's sub-dictionaries
    // keep their parent pointer on the moved-from one
    return dictionary(patched);
}


template<class CloudType>
Foam::ConvectionHeatTransfer<CloudType>::ConvectionHeatTransfer
(
    const dictionary& dict,
    CloudType& owner
)
:
    HeatTransferModel<CloudType>(withoutBird(dict), owner, typeName),
    law_(convectionLaw::New(dict.subDict(typeName + "Coeffs"))),
    voidage_
    (
        owner.mesh().template lookupObject<volScalarField>
        (
            dict.subDict(typeName + "Coeffs")
                .template lookupOrDefault<word>("voidage", "voidage")
        )
    ),
    K_(coarseGrainFactor(owner.constProps().dict()))
{}


template<class CloudType>
Foam::ConvectionHeatTransfer<CloudType>::ConvectionHeatTransfer
(
    const ConvectionHeatTransfer<CloudType>& htm
)
:
    HeatTransferModel<CloudType>(htm),
    law_(convectionLaw::New(htm.coeffDict())),
    voidage_(htm.voidage_),
    K_(htm.K_)
{}


template<class CloudType>
Foam::scalar Foam::ConvectionHeatTransfer<CloudType>::Nu
(
    const scalar,
    const scalar
) const
{
    FatalErrorInFunction
        << "heatTransferModel " << typeName << " has no Nu(Re, Pr): its law "
        << law_->type() << " needs the voidage; the cloud asks for the "
           "parcel's conductance" << abort(FatalError);
    return 0;
}


template<class CloudType>
Foam::scalar Foam::ConvectionHeatTransfer<CloudType>::htc
(
    const scalar,
    const scalar,
    const scalar,
    const scalar,
    const scalar
) const
{
    return Nu(0, 0);
}
