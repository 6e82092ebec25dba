// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "ReducingParcel.H"
#include "IOstreams.H"
#include "IOField.H"

template<class ParcelType>
Foam::string Foam::ReducingParcel<ParcelType>::propertyList_ =
    Foam::ReducingParcel<ParcelType>::propertyList();


template<class ParcelType>
Foam::ReducingParcel<ParcelType>::ReducingParcel
(
    const polyMesh& mesh,
    Istream& is,
    bool readFields,
    bool newFormat
)
:
    ParcelType(mesh, is, readFields, newFormat),
    reductionDegree_(0)
{
    if (readFields)
    {
        is >> reductionDegree_;
    }

    is.check(FUNCTION_NAME);
}


template<class ParcelType>
template<class CloudType>
void Foam::ReducingParcel<ParcelType>::readFields(CloudType& c)
{
    ParcelType::readFields(c);

    IOobject io(c.fieldIOobject("reductionDegree", IOobject::MUST_READ));
    const bool present =
        returnReduce(io.template typeHeaderOk<IOField<scalar>>(true), orOp<bool>());

    if (present)
    {
        const IOField<scalar> X(io, bool(c.size()));
        c.checkFieldIOobject(c, X);
        label i = 0;
        for (ReducingParcel<ParcelType>& p : c)
        {
            p.reductionDegree_ = X[i++];
        }
    }
    else
    {
        const scalar X0 = c.constProps().reductionDegree0();
        for (ReducingParcel<ParcelType>& p : c)
        {
            p.reductionDegree_ = X0;
        }
        if (returnReduce(c.size(), sumOp<label>()))
        {
            Info<< "    No reductionDegree in " << c.time().timeName()
                << ": the parcels start at reductionDegree0 " << X0 << endl;
        }
    }
}


template<class ParcelType>
template<class CloudType>
void Foam::ReducingParcel<ParcelType>::writeFields(const CloudType& c)
{
    ParcelType::writeFields(c);

    const label np = c.size();
    IOField<scalar> X(c.fieldIOobject("reductionDegree", IOobject::NO_READ), np);
    label i = 0;
    for (const ReducingParcel<ParcelType>& p : c)
    {
        X[i++] = p.reductionDegree_;
    }
    X.write(np > 0);
}


template<class ParcelType>
void Foam::ReducingParcel<ParcelType>::writeProperties
(
    Ostream& os,
    const wordRes& filters,
    const word& delim,
    const bool namesOnly
) const
{
    ParcelType::writeProperties(os, filters, delim, namesOnly);
    ParcelType::writeProperty
    (
        os, "reductionDegree", reductionDegree_, namesOnly, delim, filters
    );
}


template<class ParcelType>
Foam::Ostream& Foam::operator<<
(
    Ostream& os,
    const ReducingParcel<ParcelType>& p
)
{
    os  << static_cast<const ParcelType&>(p)
        << token::SPACE << p.reductionDegree();

    os.check(FUNCTION_NAME);
    return os;
}
