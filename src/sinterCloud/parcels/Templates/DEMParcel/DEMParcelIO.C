// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 sinterFoam developers

#include "DEMParcel.H"
#include "IOstreams.H"
#include "IOField.H"

template<class ParcelType>
Foam::string Foam::DEMParcel<ParcelType>::propertyList_ =
    Foam::DEMParcel<ParcelType>::propertyList();


template<class ParcelType>
Foam::DEMParcel<ParcelType>::DEMParcel
(
    const polyMesh& mesh,
    Istream& is,
    bool readFields,
    bool newFormat
)
:
    ParcelType(mesh, is, readFields, newFormat),
    displacement_(Zero),
    contacts_()
{
    if (readFields)
    {
        is >> displacement_ >> contacts_;
    }

    is.check(FUNCTION_NAME);
}


template<class ParcelType>
template<class CloudType>
void Foam::DEMParcel<ParcelType>::readFields(CloudType& c)
{
    ParcelType::readFields(c);

    // Absent when the run before used another collision model: the DEM
    // then starts without contacts, and says so
    const bool found = returnReduce
    (
        c.fieldIOobject("demContactPartner", IOobject::MUST_READ)
            .template typeHeaderOk<labelFieldCompactIOField>(true),
        orOp<bool>()
    );

    if (!found)
    {
        if (returnReduce(c.size(), sumOp<label>()))
        {
            Info<< "    No demContact fields in " << c.db().time().timeName()
                << ": parcels start without contact histories" << endl;
        }
        return;
    }

    const bool valid = c.size();

    labelFieldCompactIOField partner
    (
        c.fieldIOobject("demContactPartner", IOobject::MUST_READ),
        valid
    );
    c.checkFieldFieldIOobject(c, partner);

    vectorFieldCompactIOField faceCentre
    (
        c.fieldIOobject("demContactFaceCentre", IOobject::MUST_READ),
        valid
    );
    c.checkFieldFieldIOobject(c, faceCentre);

    vectorFieldCompactIOField spring
    (
        c.fieldIOobject("demContactSpring", IOobject::MUST_READ),
        valid
    );
    c.checkFieldFieldIOobject(c, spring);

    scalarFieldCompactIOField duration
    (
        c.fieldIOobject("demContactDuration", IOobject::MUST_READ),
        valid
    );
    c.checkFieldFieldIOobject(c, duration);

    scalarFieldCompactIOField bridge
    (
        c.fieldIOobject("demContactBridge", IOobject::MUST_READ),
        valid
    );
    c.checkFieldFieldIOobject(c, bridge);

    label i = 0;
    for (DEMParcel<ParcelType>& p : c)
    {
        const label n = spring[i].size();

        if
        (
            partner[i].size() != 2*n || faceCentre[i].size() != n
         || duration[i].size() != n || bridge[i].size() != n
        )
        {
            FatalErrorInFunction
                << "Inconsistent demContact fields of parcel " << i
                << " in " << c.db().time().timePath()
                << exit(FatalError);
        }

        p.contacts_.setSize(n);
        forAll(p.contacts_, k)
        {
            demContactRecord& r = p.contacts_[k];
            r.proc = partner[i][2*k];
            r.id = partner[i][2*k + 1];
            r.faceCentre = faceCentre[i][k];
            r.history.tangentialSpring = spring[i][k];
            r.history.duration = duration[i][k];
            r.history.bridge = bridge[i][k];
        }
        ++i;
    }
}


template<class ParcelType>
template<class CloudType>
void Foam::DEMParcel<ParcelType>::writeFields(const CloudType& c)
{
    ParcelType::writeFields(c);

    const label np = c.size();
    const bool valid = np;

    labelFieldCompactIOField partner
    (
        c.fieldIOobject("demContactPartner", IOobject::NO_READ),
        np
    );
    vectorFieldCompactIOField faceCentre
    (
        c.fieldIOobject("demContactFaceCentre", IOobject::NO_READ),
        np
    );
    vectorFieldCompactIOField spring
    (
        c.fieldIOobject("demContactSpring", IOobject::NO_READ),
        np
    );
    scalarFieldCompactIOField duration
    (
        c.fieldIOobject("demContactDuration", IOobject::NO_READ),
        np
    );
    scalarFieldCompactIOField bridge
    (
        c.fieldIOobject("demContactBridge", IOobject::NO_READ),
        np
    );

    label i = 0;
    for (const DEMParcel<ParcelType>& p : c)
    {
        const label n = p.contacts_.size();
        partner[i].setSize(2*n);
        faceCentre[i].setSize(n);
        spring[i].setSize(n);
        duration[i].setSize(n);
        bridge[i].setSize(n);

        forAll(p.contacts_, k)
        {
            const demContactRecord& r = p.contacts_[k];
            partner[i][2*k] = r.proc;
            partner[i][2*k + 1] = r.id;
            faceCentre[i][k] = r.faceCentre;
            spring[i][k] = r.history.tangentialSpring;
            duration[i][k] = r.history.duration;
            bridge[i][k] = r.history.bridge;
        }
        ++i;
    }

    partner.write(valid);
    faceCentre.write(valid);
    spring.write(valid);
    duration.write(valid);
    bridge.write(valid);
}


template<class ParcelType>
Foam::Ostream& Foam::operator<<
(
    Ostream& os,
    const DEMParcel<ParcelType>& p
)
{
    os  << static_cast<const ParcelType&>(p)
        << token::SPACE << p.displacement_
        << token::SPACE << p.contacts_;

    os.check(FUNCTION_NAME);
    return os;
}
